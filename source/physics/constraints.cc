// SPDX-License-Identifier: GPL-3.0-or-later

#include <deal.II/base/exceptions.h>

#include <ndda/base/utilities.h>
#include <ndda/kinematics/reduced_blocks.h>
#include <ndda/physics/constraints.h>

namespace ndda
{
  using namespace dealii;

  NodeLocator::NodeLocator(const CrackableMesh &mesh,
                           const DoFHandler<2> &dof_handler,
                           const DofMap        &dof_map)
    : mesh(mesh)
  {
    const auto        &fe     = dof_handler.get_fe();
    const unsigned int n_dofs = dof_map.n_dofs;
    // Which two dofs belong to the same node, and where the node is.
    partner.resize(n_dofs);
    component.resize(n_dofs);
    for (const auto &node : dof_map.node_dofs)
      for (unsigned int c = 0; c < 2; ++c)
        {
          component[node[c]] = c;
          partner[node[c]]   = node[1 - c];
        }
    support_points.resize(n_dofs);
    const auto &unit = fe.get_unit_support_points();
    for (const auto &cell : mesh.get_triangulation().active_cell_iterators())
      {
        const auto *dofs      = dof_map.dofs_of_cell(cell->active_cell_index());
        const Tensor<1, 2> e1 = cell->vertex(1) - cell->vertex(0);
        const Tensor<1, 2> e2 = cell->vertex(2) - cell->vertex(0);
        for (unsigned int i = 0; i < dof_map.dofs_per_cell; ++i)
          support_points[dofs[i]] =
            cell->vertex(0) + unit[i][0] * e1 + unit[i][1] * e2;
      }

    on_boundary.assign(n_dofs, false);
    std::vector<index> face_dofs(fe.n_dofs_per_face());
    for (const auto &cell : dof_handler.active_cell_iterators())
      for (unsigned int f = 0; f < cell->n_faces(); ++f)
        if (cell->at_boundary(f))
          {
            cell->face(f)->get_dof_indices(face_dofs);
            for (const auto dof : face_dofs)
              on_boundary[dof] = true;
          }

    const auto box = mesh.bounding_box();
    tolerance      = point_tolerance(box.first, box.second);
  }



  std::vector<NodeLocator::index>
  NodeLocator::nodes_at_vertex(const Point<2>    &p,
                               const std::string &entry) const
  {
    const auto  &vertices      = mesh.get_block_mesh().vertices;
    unsigned int best          = numbers::invalid_unsigned_int;
    double       best_distance = tolerance;
    for (unsigned int v = 0; v < vertices.size(); ++v)
      if (vertices[v].distance(p) <= best_distance)
        {
          best          = v;
          best_distance = vertices[v].distance(p);
        }
    if (best == numbers::invalid_unsigned_int)
      {
        // Outside, or inside but not a vertex (possible for imported meshes).
        AssertThrow(mesh.locate(p).first != numbers::invalid_unsigned_int,
                    ExcMessage(entry + ": the point " + to_string(p) +
                               " lies outside every block. Move it into "
                               "or onto a block."));
        AssertThrow(false,
                    ExcMessage(entry + ": the point " + to_string(p) +
                               " is not a vertex of the mesh. With an "
                               "imported mesh, give points that are mesh "
                               "vertices."));
      }
    const Point<2>     x = vertices[best];
    std::vector<index> nodes;
    for (index i = 0; i < support_points.size(); ++i)
      if (component[i] == 0 && support_points[i].distance(x) <= tolerance)
        nodes.push_back(i);
    return nodes;
  }



  std::vector<NodeLocator::index>
  NodeLocator::boundary_nodes_on(const geometry::Segment &segment) const
  {
    std::vector<index> nodes;
    for (index i = 0; i < support_points.size(); ++i)
      if (component[i] == 0 && on_boundary[i] &&
          distance_to_segment(support_points[i], segment) <= tolerance)
        nodes.push_back(i);
    return nodes;
  }



  namespace
  {
    /** The x dofs of the nodes the condition @p bc acts on (its points,
     * then the boundary nodes on its segments); @p where names it. */
    std::vector<types::global_dof_index>
    nodes_of(const parameters::BoundaryCondition &bc,
             const NodeLocator                   &nodes,
             const std::string                   &where)
    {
      using index = types::global_dof_index;
      std::vector<index> constrained_here;
      for (const auto &p : bc.points)
        for (const index i : nodes.nodes_at_vertex(p, where + "/Points"))
          constrained_here.push_back(i);
      for (const auto &segment : bc.segments)
        {
          const auto on_segment = nodes.boundary_nodes_on(segment);
          AssertThrow(!on_segment.empty(),
                      ExcMessage(where +
                                 "/Segments: no boundary vertex "
                                 "lies on the segment " +
                                 to_string(segment.a) + " - " +
                                 to_string(segment.b) +
                                 ". Give a segment along a block's "
                                 "boundary."));
          constrained_here.insert(constrained_here.end(),
                                  on_segment.begin(),
                                  on_segment.end());
        }
      return constrained_here;
    }
  } // namespace



  void
  Constraints::setup(const parameters::BoundaryConditions &conditions,
                     const parameters::ConstraintMethod    method_in,
                     const NodeLocator                    &nodes)
  {
    method = method_in;
    node_constraints.clear();
    functions.clear();
    std::vector<bool> constrained(nodes.support_points.size(), false);
    for (const auto &bc : conditions.conditions)
      {
        const std::string where    = "Boundary conditions/" + bc.name;
        unsigned int      function = numbers::invalid_unsigned_int;
        if (bc.type != parameters::ConstraintType::fixed)
          {
            function = functions.size();
            functions.push_back(std::make_unique<Expression>(
              bc.value,
              bc.type == parameters::ConstraintType::roller ? 1 : 2,
              true,
              where + "/Value"));
          }
        const double angle = bc.roller_angle * numbers::PI / 180.;
        Tensor<1, 2> normal;
        normal[0] = -std::sin(angle);
        normal[1] = std::cos(angle);

        const std::vector<index> constrained_here = nodes_of(bc, nodes, where);
        for (const auto i : constrained_here)
          {
            if (constrained[i])
              continue; // The first condition listed for a node wins.
            const index j  = nodes.partner[i];
            constrained[i] = constrained[j] = true;
            NodeConstraint nc;
            nc.dofs     = {{i, j}};
            nc.position = nodes.support_points[i];
            nc.type     = bc.type;
            nc.normal   = normal;
            nc.function = function;
            nc.name     = bc.name;
            node_constraints.push_back(nc);
          }
      }

    reduced = nullptr;
    build_lines();
  }



  void
  Constraints::tie_blocks(const kinematics::ReducedBlocks &blocks)
  {
    reduced = &blocks;
    build_lines();
  }



  bool
  Constraints::in_reduced_block(const index dof) const
  {
    return reduced != nullptr && reduced->is_reduced(dof);
  }



  void
  Constraints::build_lines()
  {
    constraints.clear();
    if (exact())
      for (const auto &nc : node_constraints)
        {
          // A reduced block's constraints are in its lines.
          if (in_reduced_block(nc.dofs[0]))
            continue;
          if (nc.type != parameters::ConstraintType::roller)
            {
              constraints.add_line(nc.dofs[0]);
              constraints.add_line(nc.dofs[1]);
            }
          else
            {
              // n . u = d: solve for the component with the larger normal
              // entry; the inhomogeneity is handled by the step's
              // prescribed increment.
              const unsigned int k =
                std::abs(nc.normal[1]) >= std::abs(nc.normal[0]) ? 1 : 0;
              constraints.add_line(nc.dofs[k]);
              constraints.add_entry(nc.dofs[k],
                                    nc.dofs[1 - k],
                                    -nc.normal[1 - k] / nc.normal[k]);
            }
        }
    if (reduced != nullptr)
      reduced->add_lines(constraints);
    constraints.close();
  }



  Tensor<1, 2>
  Constraints::target_increment(const NodeConstraint &nc,
                                const double          t0,
                                const double          dt,
                                const Vector<double> &displacement) const
  {
    Tensor<1, 2> current;
    for (unsigned int d = 0; d < 2; ++d)
      current[d] = displacement[nc.dofs[d]];
    const Point<2> x0 = nc.position - current;
    Tensor<1, 2>   target;
    switch (nc.type)
      {
        case parameters::ConstraintType::fixed:
          target = -current;
          break;
        case parameters::ConstraintType::displacement:
          {
            auto &f = *functions[nc.function];
            f.set_time(t0 + dt);
            for (unsigned int d = 0; d < 2; ++d)
              target[d] = f.value(x0, d) - current[d];
            break;
          }
        case parameters::ConstraintType::velocity:
          {
            auto &f = *functions[nc.function];
            f.set_time(t0 + 0.5 * dt);
            for (unsigned int d = 0; d < 2; ++d)
              target[d] = f.value(x0, d) * dt;
            break;
          }
        case parameters::ConstraintType::roller:
          {
            auto &f = *functions[nc.function];
            f.set_time(t0 + dt);
            // Only the normal part is prescribed.
            target = (f.value(x0, 0) - nc.normal * current) * nc.normal;
            break;
          }
      }
    return target;
  }



  void
  Constraints::check_expressions(const std::vector<double> &times)
  {
    std::vector<std::vector<Point<2>>> points(functions.size());
    for (const auto &nc : node_constraints)
      if (nc.function < functions.size())
        points[nc.function].push_back(nc.position);
    for (unsigned int f = 0; f < functions.size(); ++f)
      functions[f]->check(points[f], times);
  }



  void
  Constraints::prescribed_increment(const double          t0,
                                    const double          dt,
                                    const Vector<double> &displacement,
                                    Vector<double>       &increment) const
  {
    increment = 0;
    std::vector<Tensor<1, 2>> targets(node_constraints.size());
    for (unsigned int i = 0; i < node_constraints.size(); ++i)
      {
        const auto &nc = node_constraints[i];
        targets[i]     = target_increment(nc, t0, dt, displacement);
        if (exact() && nc.type == parameters::ConstraintType::roller)
          {
            // Put the whole normal increment on the dependent component,
            // see build_lines().
            const unsigned int k =
              std::abs(nc.normal[1]) >= std::abs(nc.normal[0]) ? 1 : 0;
            increment[nc.dofs[k]] = (targets[i] * nc.normal) / nc.normal[k];
          }
        else
          for (unsigned int d = 0; d < 2; ++d)
            increment[nc.dofs[d]] = targets[i][d];
      }
    // A reduced block takes the increment of its unknowns that meets its
    // constraints, on all of its nodes.
    if (reduced != nullptr && exact())
      reduced->prescribed_increment(targets, increment);
  }



  namespace
  {
    /** Entry (i, j) of the penalty spring of @p nc, over its stiffness. */
    double
    spring(const Constraints::NodeConstraint &nc,
           const unsigned int                 i,
           const unsigned int                 j)
    {
      return nc.type == parameters::ConstraintType::roller ?
               nc.normal[i] * nc.normal[j] :
               (i == j ? 1. : 0.);
    }
  } // namespace



  void
  Constraints::add_penalty_springs(const double          k,
                                   SparseMatrix<double> &matrix) const
  {
    for (const auto &nc : node_constraints)
      for (unsigned int i = 0; i < 2; ++i)
        for (unsigned int j = 0; j < 2; ++j)
          {
            const double kij = nc.type == parameters::ConstraintType::roller ?
                                 k * nc.normal[i] * nc.normal[j] :
                                 (i == j ? k : 0.);
            if (kij != 0.)
              matrix.add(nc.dofs[i], nc.dofs[j], kij);
          }
  }



  void
  Constraints::add_penalty_forces(const double          k,
                                  const Vector<double> &prescribed,
                                  Vector<double>       &rhs) const
  {
    for (const auto &nc : node_constraints)
      for (unsigned int i = 0; i < 2; ++i)
        for (unsigned int j = 0; j < 2; ++j)
          rhs[nc.dofs[i]] += spring(nc, i, j) * k * prescribed[nc.dofs[j]];
  }
} // namespace ndda
