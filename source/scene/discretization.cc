// SPDX-License-Identifier: GPL-3.0-or-later

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <ndda/physics/finite_element.h>
#include <ndda/scene/discretization.h>
#include <ndda/scene/scene.h>

#include <algorithm>
#include <sstream>

namespace ndda
{
  namespace scene
  {
    Discretization::Discretization(CrackableMesh       &mesh,
                                   dealii::TimerOutput &timer)
      : mesh(mesh)
      , mapping(linear_mapping())
      , dof_handler(mesh.get_triangulation())
      , timer(timer)
    {}



    Discretization::~Discretization()
    {
      dof_handler.clear();
    }



    void
    Discretization::setup_dofs(const parameters::Parameters &parameters,
                               const bool                    element_matrices)
    {
      // The element by name and what travels with it
      // (physics/finite_element.h).
      auto element = make_element(parameters.control.finite_element);
      fe           = std::move(element.system);
      face_quadrature =
        std::make_unique<Quadrature<1>>(element.face_quadrature);
      element_cache.set_quadratures(element.cell_quadrature,
                                    element.mass_quadrature);
      n_output_subdivisions = element.n_output_subdivisions;
      dof_handler.distribute_dofs(*fe);
      cell_material.resize(mesh.get_triangulation().n_active_cells());
      for (const auto &cell : mesh.get_triangulation().active_cell_iterators())
        cell_material[cell->active_cell_index()] = cell->material_id();
      dof_map.reinit(dof_handler);
      // A crack keeps the cells (and their frames).
      if (frames.cell_angles().size() != dof_map.n_cells())
        frames.reinit(dof_map.n_cells());

      if (element_matrices)
        element_cache.update(
          dof_handler, mapping, parameters.materials, false, 0.);
      double max_modulus = 0;
      for (const auto &m : parameters.materials.materials)
        max_modulus = std::max(max_modulus, m.youngs_modulus);
      penalty_stiffness = parameters.control.penalty_factor * max_modulus *
                          parameters.materials.thickness;
      linear_system.initialize(parameters.control.linear_solver,
                               parameters.control.solver_tolerance,
                               &timer);
    }



    void
    Discretization::setup_constraints(const parameters::Parameters &parameters)
    {
      const NodeLocator nodes(mesh, dof_handler, mapping);
      if (parameters.control.linear_solver ==
          parameters::LinearSolverType::cg_amg)
        linear_system.get_linear_solver().set_rigid_body_modes(
          nodes.support_points, nodes.component);
      constraints.setup(parameters.boundary_conditions,
                        parameters.control.constraint_method,
                        nodes);
      // Bolts couple two nodes that may lie in different blocks.
      bolts.setup(parameters.bolts, nodes);
    }



    void
    Discretization::setup_kinematics(const parameters::Parameters &parameters)
    {
      models.clear();
      const auto states = initial_states(parameters, mesh);
      std::vector<const kinematics::BlockKinematics *> block_model;
      for (const auto &state : states)
        {
          auto known =
            std::find_if(models.begin(), models.end(), [&](const auto &m) {
              return m.first == state.kinematics;
            });
          if (known == models.end())
            {
              models.emplace_back(state.kinematics,
                                  kinematics::BlockKinematicsRegistry::create(
                                    state.kinematics));
              known = models.end() - 1;
            }
          block_model.push_back(known->second.get());
        }
      cell_model.resize(mesh.get_triangulation().n_active_cells());
      for (unsigned int c = 0; c < cell_model.size(); ++c)
        cell_model[c] = block_model[mesh.block_of_cell(c)];
    }



    void
    Discretization::setup_system(const parameters::Parameters &parameters)
    {
      frames.setup(mesh, dof_map, constraints, bolts);
      linear_system.set_frames(&frames);
      // The model of each block: that of its cells (a crack keeps them).
      std::vector<const kinematics::BlockKinematics *> block_model(
        mesh.n_blocks(), nullptr);
      for (unsigned int c = 0; c < cell_model.size(); ++c)
        block_model[mesh.block_of_cell(c)] = cell_model[c];
      reduced_blocks.setup(mesh, dof_map, frames, block_model, constraints);
      constraints.tie_blocks(reduced_blocks);

      DynamicSparsityPattern dsp(dof_handler.n_dofs());
      DoFTools::make_sparsity_pattern(dof_handler,
                                      dsp,
                                      constraints.affine_constraints(),
                                      true);
      bolts.add_couplings(dsp);
      // Rigid and affine blocks constrain most of their dofs: the solver
      // gets the system of the free dofs alone (direct solvers).
      linear_system.reinit(dsp,
                           constraints,
                           parameters.contact.enabled,
                           !reduced_blocks.empty() &&
                             parameters.control.linear_solver !=
                               parameters::LinearSolverType::cg_amg);
    }



    void
    Discretization::setup_loads(const parameters::Parameters &parameters)
    {
      loads.setup(parameters.loads, mesh, dof_handler, dof_map);
      loads.update_faces(dof_handler,
                         mapping,
                         *face_quadrature,
                         parameters.materials.thickness);
    }



    bool
    Discretization::update_matrices(const parameters::Parameters &parameters,
                                    const bool            only_moved_cells,
                                    const Vector<double> &displacement,
                                    const StressField    &stresses,
                                    const bool            always_assemble)
    {
      const double tolerance = parameters.control.matrix_update_tolerance;
      // A tangent that depends on the stress is rebuilt on the first step
      // too (setup_dofs() did not know the initial stresses).
      const bool recompute =
        only_moved_cells ||
        ElementCache<2>::tangent_depends_on_stress(parameters.materials);
      if (recompute &&
          element_cache.update(dof_handler,
                               mapping,
                               parameters.materials,
                               tolerance > 0.,
                               tolerance,
                               &stresses.cells(),
                               &frames.cell_angles()) == 0 &&
          !always_assemble)
        return false;
      assemble(displacement);
      loads.update_gravity(linear_system.get_mass_matrix(), dof_map);
      if (only_moved_cells)
        loads.update_faces(dof_handler,
                           mapping,
                           *face_quadrature,
                           parameters.materials.thickness);
      return true;
    }



    void
    Discretization::assemble(const Vector<double> &displacement)
    {
      linear_system.assemble(element_cache, dof_map, bolts, displacement);
    }



    void
    Discretization::external_force(const double          t,
                                   const Vector<double> &displacement,
                                   Vector<double>       &force) const
    {
      force.reinit(dof_handler.n_dofs());
      loads.add(t, force);
      // Bolt pretension pulls the anchors together.
      bolts.add_pretension(displacement, force);
    }



    std::string
    Discretization::summary() const
    {
      std::ostringstream out;
      out << "  blocks: " << mesh.n_blocks();
      if (!reduced_blocks.empty())
        {
          // The blocks of each model, e.g. "(rigid 2, meshed 5)".
          std::string separator = " (";
          for (const auto &[name, model] : models)
            {
              out << separator << name << " "
                  << (model->n_unknowns() == 0 ?
                        mesh.n_blocks() - reduced_blocks.n_reduced() :
                        reduced_blocks.n_blocks_of(model.get()));
              separator = ", ";
            }
          out << ")";
        }
      out << ", cells: " << mesh.get_triangulation().n_active_cells()
          << ", vertices: " << mesh.get_triangulation().n_vertices()
          << ", degrees of freedom: " << dof_handler.n_dofs() << " ("
          << fe->base_element(0).get_name() << ")\n"
          << "  constrained nodes: " << constraints.constrained_nodes().size();
      return out.str();
    }



    Vector<double>
    Discretization::initial_inertia_force(
      const double          t,
      const Vector<double> &displacement,
      const Vector<double> &internal_force) const
    {
      Vector<double> rhs;
      external_force(t, displacement, rhs);
      rhs -= internal_force;
      Vector<double> acceleration;
      linear_system.solve_mass(rhs, constraints, acceleration);
      Vector<double> inertia_force(acceleration.size());
      linear_system.get_mass_matrix().vmult(inertia_force, acceleration);
      return inertia_force;
    }
  } // namespace scene
} // namespace ndda
