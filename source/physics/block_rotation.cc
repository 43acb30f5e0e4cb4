// SPDX-License-Identifier: GPL-3.0-or-later

#include <ndda/physics/block_rotation.h>
#include <ndda/physics/rotation.h>

namespace ndda
{
  namespace
  {
    /** What rotate_blocks() needs of a block. */
    struct Block
    {
      /// Sum of area * rotation and of area over its cells.
      double spin = 0, area = 0;
      /// Sums over the nodes that define the centre, and their weight.
      Tensor<1, 2> position, velocity, acceleration;
      double       weight = 0;
      /// Its number of constrained nodes.
      unsigned int constrained = 0;

      /**
       * Add a node at @p x of mass @p m, velocity @p v and inertia force
       * @p f to the sums of the centre: weighted by its mass (the centre
       * of mass), or by one for a constrained block (the mean of the
       * constrained nodes, whose accelerations are f / m).
       */
      void
      add_node(const Point<2>     &x,
               const double        m,
               const Tensor<1, 2> &v,
               const Tensor<1, 2> &f)
      {
        const double w = constrained > 0 ? 1. : m;
        position += w * x;
        velocity += w * v;
        acceleration += constrained > 0 && m > 0. ? f / m : f;
        weight += w;
      }
    };

    /** The present position of every node (the straight-sided cells'
     * affine map of the element's unit support points). */
    std::vector<Point<2>>
    node_positions(const CrackableMesh   &mesh,
                   const DofMap          &dof_map,
                   const ElementCache<2> &element_cache)
    {
      const auto           &vertices = mesh.get_triangulation().get_vertices();
      const auto           &support  = dof_map.fe->get_unit_support_points();
      std::vector<Point<2>> position(dof_map.node_dofs.size());
      for (unsigned int c = 0; c < dof_map.n_cells(); ++c)
        {
          const auto        &v    = element_cache[c].vertex_indices;
          const auto        *dofs = dof_map.dofs_of_cell(c);
          const Tensor<1, 2> e1   = vertices[v[1]] - vertices[v[0]];
          const Tensor<1, 2> e2   = vertices[v[2]] - vertices[v[0]];
          for (unsigned int i = 0; i < dof_map.dofs_per_cell; ++i)
            if (dof_map.local_component[i] == 0)
              position[dof_map.dof_to_node[dofs[i]]] =
                vertices[v[0]] + support[i][0] * e1 + support[i][1] * e2;
        }
      return position;
    }

    /** The sum of row @p row of @p matrix. */
    double
    row_sum(const SparseMatrix<double>   &matrix,
            const types::global_dof_index row)
    {
      double sum = 0;
      for (auto entry = matrix.begin(row); entry != matrix.end(row); ++entry)
        sum += entry->value();
      return sum;
    }



    /** Turn the vector at dofs @p dofs of @p v relative to @p centre by
     * the rotation of cos @p c and sin @p s. */
    void
    turn_about(Vector<double>                               &v,
               const std::array<types::global_dof_index, 2> &dofs,
               const Tensor<1, 2>                           &centre,
               const double                                  c,
               const double                                  s)
    {
      const double x = v[dofs[0]] - centre[0], y = v[dofs[1]] - centre[1];
      v[dofs[0]] = centre[0] + c * x - s * y;
      v[dofs[1]] = centre[1] + s * x + c * y;
    }
  } // namespace



  std::vector<double>
  rotate_blocks(const CrackableMesh        &mesh,
                const DofMap               &dof_map,
                const ElementCache<2>      &element_cache,
                const StressField          &stresses,
                const Constraints          &constraints,
                const SparseMatrix<double> &mass,
                Vector<double>             &d,
                Vector<double>             &velocity,
                Vector<double>             &inertia_force)
  {
    const unsigned int        n_nodes = dof_map.node_dofs.size();
    std::vector<Block>        blocks(mesh.n_blocks());
    std::vector<unsigned int> node_block(n_nodes,
                                         numbers::invalid_unsigned_int);
    for (unsigned int c = 0; c < dof_map.n_cells(); ++c)
      {
        const auto [spin, area] = stresses.cell_rotation(c, d);
        Block &block            = blocks[mesh.block_of_cell(c)];
        block.spin += spin;
        block.area += area;
        const auto *dofs = dof_map.dofs_of_cell(c);
        for (unsigned int i = 0; i < dof_map.dofs_per_cell; ++i)
          node_block[dof_map.dof_to_node[dofs[i]]] = mesh.block_of_cell(c);
      }
    std::vector<bool> constrained(n_nodes, false);
    for (const auto &node : constraints.constrained_nodes())
      {
        const unsigned int n = dof_map.dof_to_node[node.dofs[0]];
        if (!constrained[n])
          ++blocks[node_block[n]].constrained;
        constrained[n] = true;
      }

    // The centre of each block, its velocity and acceleration: the
    // mass-weighted means over its nodes, or the plain means over its
    // constrained nodes. Nodal masses are the row sums of the mass matrix
    // (1^T M v is the momentum for the consistent mass too).
    const std::vector<Point<2>> position =
      node_positions(mesh, dof_map, element_cache);
    std::vector<double> node_mass(n_nodes);
    for (unsigned int n = 0; n < n_nodes; ++n)
      {
        if (node_block[n] == numbers::invalid_unsigned_int)
          continue;
        const auto &dofs = dof_map.node_dofs[n];
        node_mass[n]     = row_sum(mass, dofs[0]);
        Block &block     = blocks[node_block[n]];
        if (block.constrained > 0 && !constrained[n])
          continue;
        block.add_node(position[n],
                       node_mass[n],
                       Tensor<1, 2>({velocity[dofs[0]], velocity[dofs[1]]}),
                       Tensor<1, 2>(
                         {inertia_force[dofs[0]], inertia_force[dofs[1]]}));
      }

    std::vector<double> rotation(blocks.size());
    for (unsigned int b = 0; b < blocks.size(); ++b)
      if (blocks[b].weight > 0. && blocks[b].area > 0. &&
          blocks[b].constrained <= 1)
        rotation[b] = blocks[b].spin / blocks[b].area;

    for (unsigned int n = 0; n < n_nodes; ++n)
      {
        if (node_block[n] == numbers::invalid_unsigned_int ||
            rotation[node_block[n]] == 0.)
          continue;
        const Block &block              = blocks[node_block[n]];
        const double theta              = rotation[node_block[n]];
        const auto [cos_minus_one, sin] = rotation::cos_minus_one_sin(theta);
        const auto        &dofs         = dof_map.node_dofs[n];
        const Tensor<1, 2> r = position[n] - block.position / block.weight;
        // (R - I - theta J) r: the exact rotation less the linear one.
        d[dofs[0]] += cos_minus_one * r[0] - (sin - theta) * r[1];
        d[dofs[1]] += cos_minus_one * r[1] + (sin - theta) * r[0];
        const double c = 1. + cos_minus_one;
        turn_about(velocity, dofs, block.velocity / block.weight, c, sin);
        turn_about(inertia_force,
                   dofs,
                   node_mass[n] * block.acceleration / block.weight,
                   c,
                   sin);
      }
    return rotation;
  }



  void
  BlockFrames::reinit(const unsigned int n_cells)
  {
    angle.assign(n_cells, 0.);
    any_turned = false;
  }



  void
  BlockFrames::setup(const CrackableMesh &mesh,
                     const DofMap        &dof_map,
                     const Constraints   &constraints,
                     const BoltSprings   &bolts)
  {
    this->dof_map = &dof_map;
    AssertDimension(angle.size(), dof_map.n_cells());
    cell_block.resize(dof_map.n_cells());
    std::vector<unsigned int> node_block(dof_map.node_dofs.size());
    for (unsigned int c = 0; c < dof_map.n_cells(); ++c)
      {
        cell_block[c]    = mesh.block_of_cell(c);
        const auto *dofs = dof_map.dofs_of_cell(c);
        for (unsigned int i = 0; i < dof_map.dofs_per_cell; ++i)
          node_block[dof_map.dof_to_node[dofs[i]]] = cell_block[c];
      }
    global_frame.assign(mesh.n_blocks(), false);
    // A constraint of both components (fixed, displacement, velocity)
    // holds in any frame: d = g at a node is Q^T d = Q^T g. A roller's
    // direction is global.
    for (const auto &node : constraints.constrained_nodes())
      if (node.type == parameters::ConstraintType::roller)
        global_frame[node_block[dof_map.dof_to_node[node.dofs[0]]]] = true;
    for (const auto dof : bolts.anchor_dofs())
      global_frame[node_block[dof_map.dof_to_node[dof]]] = true;
    for (unsigned int c = 0; c < angle.size(); ++c)
      if (global_frame[cell_block[c]])
        angle[c] = 0.;
    update_nodes();
  }



  void
  BlockFrames::turn(const std::vector<double> &block_rotation)
  {
    for (unsigned int c = 0; c < angle.size(); ++c)
      if (!global_frame[cell_block[c]])
        angle[c] += block_rotation[cell_block[c]];
    update_nodes();
  }



  void
  BlockFrames::update_nodes()
  {
    const unsigned int n_nodes = dof_map->node_dofs.size();
    node_cos.assign(n_nodes, 1.);
    node_sin.assign(n_nodes, 0.);
    any_turned = false;
    for (unsigned int c = 0; c < angle.size(); ++c)
      {
        if (angle[c] == 0.)
          continue;
        any_turned        = true;
        const double cs   = std::cos(angle[c]);
        const double sn   = std::sin(angle[c]);
        const auto  *dofs = dof_map->dofs_of_cell(c);
        for (unsigned int i = 0; i < dof_map->dofs_per_cell; ++i)
          {
            node_cos[dof_map->dof_to_node[dofs[i]]] = cs;
            node_sin[dof_map->dof_to_node[dofs[i]]] = sn;
          }
      }
  }



  void
  BlockFrames::to_frame(Vector<double> &v) const
  {
    for (unsigned int n = 0; n < node_cos.size(); ++n)
      {
        const auto  &dofs = dof_map->node_dofs[n];
        const double x = v[dofs[0]], y = v[dofs[1]];
        v[dofs[0]] = node_cos[n] * x + node_sin[n] * y;
        v[dofs[1]] = -node_sin[n] * x + node_cos[n] * y;
      }
  }



  void
  BlockFrames::to_global(Vector<double> &v) const
  {
    for (unsigned int n = 0; n < node_cos.size(); ++n)
      {
        const auto  &dofs = dof_map->node_dofs[n];
        const double x = v[dofs[0]], y = v[dofs[1]];
        v[dofs[0]] = node_cos[n] * x - node_sin[n] * y;
        v[dofs[1]] = node_sin[n] * x + node_cos[n] * y;
      }
  }



  void
  BlockFrames::turn(const ArrayView<const index> &dofs,
                    FullMatrix<double>           &k) const
  {
    // Rows (Q^T k), then columns (k Q), on each node's x dof and its
    // partner among @p dofs: [x; y] <- [c x + s y; -s x + c y]. Nodes in
    // the global frame (sin 0: reduced blocks, blocks that have not
    // turned) are left as they are.
    const unsigned int n = dofs.size();
    for (unsigned int i = 0; i < n; ++i)
      {
        const unsigned int node = dof_map->dof_to_node[dofs[i]];
        if (node_sin[node] == 0. || dofs[i] != dof_map->node_dofs[node][0])
          continue;
        const auto   y = dof_map->node_dofs[node][1];
        unsigned int p = 0;
        while (p < n && dofs[p] != y)
          ++p;
        if (p == n)
          continue;
        const double c = node_cos[node], s = node_sin[node];
        for (unsigned int j = 0; j < n; ++j)
          {
            const double x = k(i, j), y = k(p, j);
            k(i, j) = c * x + s * y;
            k(p, j) = -s * x + c * y;
          }
        for (unsigned int j = 0; j < n; ++j)
          {
            const double x = k(j, i), y = k(j, p);
            k(j, i) = c * x + s * y;
            k(j, p) = -s * x + c * y;
          }
      }
  }
} // namespace ndda
