// SPDX-License-Identifier: GPL-3.0-or-later

#include <ndda/physics/block_rotation.h>
#include <ndda/physics/rotation.h>

#include <algorithm>

namespace ndda
{
  namespace
  {
    /** What rotate_blocks() needs of a block. */
    struct Block
    {
      /// Sums over the nodes that define the centre, and their weight.
      Tensor<1, 2> position, velocity, acceleration, increment;
      /// The sum of the acceleration vector (a scheme that keeps one),
      /// weighted as the velocity.
      Tensor<1, 2> kept_acceleration;
      double       weight = 0;
      /// Its number of constrained nodes.
      unsigned int constrained = 0;

      /**
       * Add a node at @p x of mass @p m, velocity @p v, inertia force
       * @p f and increment @p u to the sums of the centre: weighted by its
       * mass (the centre of mass), or by one for a constrained block (the
       * mean of the constrained nodes, whose accelerations are f / m).
       */
      void
      add_node(const Point<2>     &x,
               const double        m,
               const Tensor<1, 2> &v,
               const Tensor<1, 2> &f,
               const Tensor<1, 2> &u)
      {
        const double w = constrained > 0 ? 1. : m;
        position += w * x;
        velocity += w * v;
        increment += w * u;
        acceleration += constrained > 0 && m > 0. ? f / m : f;
        weight += w;
      }
    };

    /** The present position of every node (the straight-sided cells'
     * affine map of the element's unit support points). */
    std::vector<Point<2>>
    node_positions(const CrackableMesh &mesh, const DofMap &dof_map)
    {
      const auto           &vertices = mesh.get_triangulation().get_vertices();
      const auto           &support  = dof_map.fe->get_unit_support_points();
      std::vector<Point<2>> position(dof_map.node_dofs.size());
      for (unsigned int c = 0; c < dof_map.n_cells(); ++c)
        {
          const unsigned int *v    = dof_map.vertices_of_cell(c);
          const auto         *dofs = dof_map.dofs_of_cell(c);
          const Tensor<1, 2>  e1   = vertices[v[1]] - vertices[v[0]];
          const Tensor<1, 2>  e2   = vertices[v[2]] - vertices[v[0]];
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



  void
  BlockNodes::setup(const CrackableMesh        &mesh,
                    const DofMap               &dof_map,
                    const Constraints          &constraints,
                    const SparseMatrix<double> &mass_matrix)
  {
    const unsigned int n_nodes = dof_map.node_dofs.size();
    block.assign(n_nodes, numbers::invalid_unsigned_int);
    constrained.assign(n_nodes, false);
    n_constrained.assign(mesh.n_blocks(), 0);
    mass.assign(n_nodes, 0.);
    for (unsigned int c = 0; c < dof_map.n_cells(); ++c)
      {
        const auto *dofs = dof_map.dofs_of_cell(c);
        for (unsigned int i = 0; i < dof_map.dofs_per_cell; ++i)
          block[dof_map.dof_to_node[dofs[i]]] = mesh.block_of_cell(c);
      }
    for (const auto &node : constraints.constrained_nodes())
      {
        const unsigned int n = dof_map.dof_to_node[node.dofs[0]];
        if (!constrained[n])
          ++n_constrained[block[n]];
        constrained[n] = true;
      }
    for (unsigned int n = 0; n < n_nodes; ++n)
      if (block[n] != numbers::invalid_unsigned_int)
        mass[n] = row_sum(mass_matrix, dof_map.node_dofs[n][0]);
  }



  std::vector<double>
  block_rotations(const CrackableMesh  &mesh,
                  const DofMap         &dof_map,
                  const StressField    &stresses,
                  const BlockNodes     &nodes,
                  const Vector<double> &d)
  {
    std::vector<double> spin(mesh.n_blocks(), 0.), area(mesh.n_blocks(), 0.);
    // The cells of a block held at two or more nodes are not visited:
    // its rotation is 0 whatever they hold.
    for (unsigned int c = 0; c < dof_map.n_cells(); ++c)
      {
        const unsigned int b = mesh.block_of_cell(c);
        if (nodes.n_constrained[b] > 1)
          continue;
        const auto [s, a] = stresses.cell_rotation(c, d);
        spin[b] += s;
        area[b] += a;
      }
    std::vector<double> rotation(mesh.n_blocks(), 0.);
    for (unsigned int b = 0; b < rotation.size(); ++b)
      if (area[b] > 0. && nodes.n_constrained[b] <= 1)
        rotation[b] = spin[b] / area[b];
    return rotation;
  }



  void
  add_rotation_correction(const CrackableMesh       &mesh,
                          const DofMap              &dof_map,
                          const ElementCache<2>     &element_cache,
                          const BlockFrames         &frames,
                          const std::vector<double> &rotation,
                          const Vector<double>      &d,
                          Vector<double>            &rhs)
  {
    // Per cell of a turning block, v = (I - R^T) d + theta R^T J (x - x_0)
    // at its nodes (x_0 its first node: K takes no force from a constant),
    // in the frame of the block; k v is the cell's share of Q K Q^T v.
    const std::vector<Point<2>> position = node_positions(mesh, dof_map);
    const unsigned int          n_dofs   = dof_map.dofs_per_cell;
    Vector<double>              z(rhs.size());
    std::vector<double>         v(n_dofs), kv(n_dofs);
    for (unsigned int c = 0; c < dof_map.n_cells(); ++c)
      {
        const double theta = rotation[mesh.block_of_cell(c)];
        if (theta == 0.)
          continue;
        const auto [cos_minus_one, sin] = rotation::cos_minus_one_sin(theta);
        const double    cos             = 1. + cos_minus_one;
        const auto     *dofs            = dof_map.dofs_of_cell(c);
        const Point<2> &origin = position[dof_map.dof_to_node[dofs[0]]];
        for (unsigned int i = 0; i < n_dofs; ++i)
          {
            const unsigned int node = dof_map.dof_to_node[dofs[i]];
            const auto        &nd   = dof_map.node_dofs[node];
            const double       dx = d[nd[0]], dy = d[nd[1]];
            const Tensor<1, 2> r = position[node] - origin;
            // a = d - R^T (d - theta J r), global components
            const double bx = dx + theta * r[1], by = dy - theta * r[0];
            const double ax     = dx - (cos * bx + sin * by);
            const double ay     = dy - (-sin * bx + cos * by);
            const auto [qc, qs] = frames.node_rotation(node);
            v[i] = dof_map.local_component[i] == 0 ? qc * ax + qs * ay :
                                                     -qs * ax + qc * ay;
          }
        const auto k = element_cache[c].stiffness;
        for (unsigned int i = 0; i < n_dofs; ++i)
          {
            double sum = 0;
            for (unsigned int j = 0; j < n_dofs; ++j)
              sum += k(i, j) * v[j];
            z[dofs[i]] += sum;
          }
      }
    frames.to_global(z);
    rhs += z;
  }



  std::vector<double>
  rotate_blocks(const CrackableMesh       &mesh,
                const DofMap              &dof_map,
                const StressField         &stresses,
                const BlockNodes          &nodes,
                const std::vector<double> &solved_rotation,
                const double               dt,
                Vector<double>            &d,
                Vector<double>            &velocity,
                Vector<double>            &inertia_force,
                Vector<double>            *acceleration)
  {
    const unsigned int n_nodes = dof_map.node_dofs.size();
    AssertDimension(nodes.block.size(), n_nodes);
    std::vector<double> rotation =
      solved_rotation.empty() ?
        block_rotations(mesh, dof_map, stresses, nodes, d) :
        solved_rotation;
    AssertDimension(rotation.size(), mesh.n_blocks());
    // No block turned: nothing to correct.
    if (std::all_of(rotation.begin(), rotation.end(), [](const double theta) {
          return theta == 0.;
        }))
      return rotation;
    const auto        &node_block  = nodes.block;
    const auto        &constrained = nodes.constrained;
    const auto        &node_mass   = nodes.mass;
    std::vector<Block> blocks(mesh.n_blocks());
    for (unsigned int b = 0; b < blocks.size(); ++b)
      blocks[b].constrained = nodes.n_constrained[b];

    // The centre of each block, its velocity, acceleration and increment:
    // the mass-weighted means over its nodes, or the plain means over its
    // constrained nodes.
    const std::vector<Point<2>> position = node_positions(mesh, dof_map);
    for (unsigned int n = 0; n < n_nodes; ++n)
      {
        if (node_block[n] == numbers::invalid_unsigned_int)
          continue;
        const auto &dofs  = dof_map.node_dofs[n];
        Block      &block = blocks[node_block[n]];
        if (block.constrained > 0 && !constrained[n])
          continue;
        block.add_node(position[n],
                       node_mass[n],
                       Tensor<1, 2>({velocity[dofs[0]], velocity[dofs[1]]}),
                       Tensor<1, 2>(
                         {inertia_force[dofs[0]], inertia_force[dofs[1]]}),
                       Tensor<1, 2>({d[dofs[0]], d[dofs[1]]}));
        if (acceleration != nullptr)
          block.kept_acceleration +=
            (block.constrained > 0 ? 1. : node_mass[n]) *
            Tensor<1, 2>({(*acceleration)[dofs[0]], (*acceleration)[dofs[1]]});
      }

    for (unsigned int b = 0; b < blocks.size(); ++b)
      if (blocks[b].weight == 0.)
        rotation[b] = 0.;
    // Each node's deformation over the step (turned to its end) and its
    // position from the centre (turned): the sums of their mass-weighted
    // products over each block.
    std::vector<Tensor<1, 2>> deformation(n_nodes), radial(n_nodes);
    std::vector<double>       radial_deformation(blocks.size(), 0.),
      radial_size(blocks.size(), 0.);

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
        // The node's deformation over the step, w = d - d_c - theta J r,
        // turned to the step's end: R w.
        const double c = 1. + cos_minus_one;
        const double wx =
          d[dofs[0]] - block.increment[0] / block.weight + theta * r[1];
        const double wy =
          d[dofs[1]] - block.increment[1] / block.weight - theta * r[0];
        const Tensor<1, 2> turned_w({c * wx - sin * wy, sin * wx + c * wy});
        // (R - I - theta J) r: the exact rotation less the linear one.
        d[dofs[0]] += cos_minus_one * r[0] - (sin - theta) * r[1];
        d[dofs[1]] += cos_minus_one * r[1] + (sin - theta) * r[0];
        turn_about(velocity, dofs, block.velocity / block.weight, c, sin);
        deformation[n] = turned_w;
        radial[n] =
          Tensor<1, 2>({c * r[0] - sin * r[1], sin * r[0] + c * r[1]});
        radial_deformation[node_block[n]] +=
          node_mass[n] * (radial[n] * turned_w);
        radial_size[node_block[n]] += node_mass[n] * (radial[n] * radial[n]);
        turn_about(inertia_force,
                   dofs,
                   node_mass[n] * block.acceleration / block.weight,
                   c,
                   sin);
        if (acceleration != nullptr)
          turn_about(*acceleration,
                     dofs,
                     block.kept_acceleration / block.weight,
                     c,
                     sin);
      }

    // The Coriolis term that turning leaves out: the block's spin
    // theta / dt times J R w, without the part of w along the radial
    // field R r, which would change the block's spin (doc/theory.md,
    // "Spin and strain").
    for (unsigned int n = 0; n < n_nodes; ++n)
      {
        const unsigned int b = node_block[n];
        if (b == numbers::invalid_unsigned_int || rotation[b] == 0.)
          continue;
        const Tensor<1, 2> w =
          deformation[n] -
          (radial_size[b] > 0. ? radial_deformation[b] / radial_size[b] : 0.) *
            radial[n];
        const auto &dofs = dof_map.node_dofs[n];
        velocity[dofs[0]] += rotation[b] / dt * w[1];
        velocity[dofs[1]] -= rotation[b] / dt * w[0];
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
  BlockFrames::carry_to_cells(const std::vector<unsigned int> &cell_origin)
  {
    std::vector<double> carried(cell_origin.size());
    for (unsigned int c = 0; c < cell_origin.size(); ++c)
      {
        AssertIndexRange(cell_origin[c], angle.size());
        carried[c] = angle[cell_origin[c]];
      }
    angle.swap(carried);
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
