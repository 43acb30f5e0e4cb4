// SPDX-License-Identifier: GPL-3.0-or-later

#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <ndda/parallel/shared_mesh.h>
#include <ndda/physics/blas.h>
#include <ndda/physics/finite_element.h>
#include <ndda/scene/discretization.h>
#include <ndda/scene/scene.h>

#include <algorithm>
#include <sstream>

namespace ndda
{
  namespace scene
  {
    Discretization::Discretization(CrackableMesh &mesh, SectionTimer &timer)
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
      number_dofs_as_on_one_process(dof_handler);
      cell_material.resize(mesh.get_triangulation().n_active_cells());
      for (const auto &cell : mesh.get_triangulation().active_cell_iterators())
        cell_material[cell->active_cell_index()] = cell->material_id();
      dof_map.reinit(dof_handler);
      owned_cells.set_communicator(communicator);
      owned_cells.reinit(mesh.get_triangulation());
      element_cache.set_owned_cells(&owned_cells);
      // A crack keeps the cells (and their frames).
      if (frames.cell_angles().size() != dof_map.n_cells())
        frames.reinit(dof_map.n_cells());

      if (element_matrices)
        element_cache.update(
          dof_handler, dof_map, mapping, parameters.materials, false, 0.);
      double max_modulus = 0;
      for (const auto &m : parameters.materials.materials)
        max_modulus = std::max(max_modulus, m.youngs_modulus);
      penalty_stiffness = parameters.control.penalty_factor * max_modulus *
                          parameters.materials.thickness;
      linear_system.initialize(parameters.control.linear_solver,
                               parameters.control.solver_tolerance,
                               &timer,
                               communicator);
    }



    void
    Discretization::setup_constraints(const parameters::Parameters &parameters)
    {
      const NodeLocator nodes(mesh, dof_handler, dof_map);
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
      // An auto block starts with the start model; the meshed model is
      // there for its promotion.
      const std::string &start =
        parameters.control.automatic_kinematics.start_model;
      std::vector<const kinematics::BlockKinematics *> block_model;
      std::vector<bool>                                block_auto;
      for (const auto &state : states)
        {
          const bool automatic = state.kinematics == kinematics::automatic_name;
          block_auto.push_back(automatic);
          block_model.push_back(model(automatic ? start : state.kinematics));
          if (automatic)
            model("meshed");
        }
      cell_model.resize(mesh.get_triangulation().n_active_cells());
      cell_auto.resize(cell_model.size());
      for (unsigned int c = 0; c < cell_model.size(); ++c)
        {
          cell_model[c] = block_model[mesh.block_of_cell(c)];
          cell_auto[c]  = block_auto[mesh.block_of_cell(c)];
        }
    }



    const kinematics::BlockKinematics *
    Discretization::model(const std::string &name)
    {
      auto known = std::find_if(models.begin(),
                                models.end(),
                                [&](const auto &m) { return m.first == name; });
      if (known != models.end())
        return known->second.get();
      models.emplace_back(name,
                          kinematics::BlockKinematicsRegistry::create(name));
      return models.back().second.get();
    }



    void
    Discretization::set_block_models(
      const std::vector<unsigned int>   &blocks,
      const kinematics::BlockKinematics *block_model)
    {
      std::vector<bool> selected(mesh.n_blocks(), false);
      for (const unsigned int b : blocks)
        selected[b] = true;
      for (unsigned int c = 0; c < cell_model.size(); ++c)
        if (selected[mesh.block_of_cell(c)])
          cell_model[c] = block_model;
    }



    std::vector<unsigned int>
    Discretization::blocks_per_model() const
    {
      std::vector<unsigned int> count;
      for (const auto &[name, m] : models)
        count.push_back(m->n_unknowns() == 0 ?
                          mesh.n_blocks() - reduced_blocks.n_reduced() :
                          reduced_blocks.n_blocks_of(m.get()));
      return count;
    }



    std::vector<bool>
    Discretization::meshed_blocks() const
    {
      std::vector<bool> meshed(mesh.n_blocks(), true);
      for (unsigned int c = 0; c < cell_model.size(); ++c)
        if (cell_model[c]->n_unknowns() > 0)
          meshed[mesh.block_of_cell(c)] = false;
      return meshed;
    }



    std::vector<bool>
    Discretization::reduced_mesh_blocks() const
    {
      std::vector<bool> reduced = meshed_blocks();
      reduced.flip();
      return reduced;
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
      straining.assign(mesh.n_blocks(), true);
      for (unsigned int c = 0; c < cell_model.size(); ++c)
        if (!cell_model[c]->strains())
          straining[mesh.block_of_cell(c)] = false;
      reduced_blocks.setup(mesh, dof_map, frames, block_model, constraints);
      constraints.tie_blocks(reduced_blocks);

      DynamicSparsityPattern dsp(dof_handler.n_dofs());
      make_whole_sparsity_pattern(dof_handler,
                                  dsp,
                                  constraints.affine_constraints());
      bolts.add_couplings(dsp);
      // Rigid and affine blocks constrain most of their dofs: the solver
      // gets the system of the free dofs alone (direct solvers).
      linear_system.reinit(dsp,
                           constraints,
                           parameters.contact.enabled,
                           !reduced_blocks.empty() &&
                             parameters.control.linear_solver !=
                               parameters::LinearSolverType::cg_amg);
      // The solvers that split the rows among the processes give each
      // process the rows of the dofs it owns in the shared triangulation.
      if (is_shared(mesh.get_triangulation()))
        {
          const std::vector<unsigned int> owner = dof_owners(dof_handler);
          std::vector<unsigned int>       row_owner;
          if (linear_system.is_compact())
            for (const auto i : linear_system.get_free_dofs())
              row_owner.push_back(owner[i]);
          else
            row_owner = owner;
          linear_system.get_linear_solver().set_row_owners(row_owner);
        }
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



    void
    Discretization::check_expressions(const parameters::Parameters &parameters)
    {
      const std::vector<double> times =
        Expression::check_times(parameters.control.end_time);
      loads.check_expressions(times);
      constraints.check_expressions(times);
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
      const unsigned int n_computed =
        recompute ? element_cache.update(dof_handler,
                                         dof_map,
                                         mapping,
                                         parameters.materials,
                                         tolerance > 0.,
                                         tolerance,
                                         &stresses.values(),
                                         &frames.cell_angles()) :
                    0;
      if (recompute && n_computed == 0 && !always_assemble)
        return false;
      assemble(displacement,
               n_computed > 0 ? &element_cache.get_computed_cells() : nullptr);
      loads.update_gravity(linear_system.get_mass_matrix(), dof_map);
      if (only_moved_cells)
        loads.update_faces(dof_handler,
                           mapping,
                           *face_quadrature,
                           parameters.materials.thickness);
      return true;
    }



    void
    Discretization::assemble(const Vector<double>            &displacement,
                             const std::vector<unsigned int> *changed_cells)
    {
      linear_system.assemble(
        element_cache, dof_map, bolts, displacement, changed_cells);
      block_nodes.setup(mesh,
                        dof_map,
                        constraints,
                        linear_system.get_mass_matrix());
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
      if (!all_meshed())
        {
          // The blocks of each model, e.g. "(rigid 2, meshed 5)".
          std::string separator = " (";
          const auto  count     = blocks_per_model();
          for (unsigned int m = 0; m < models.size(); ++m)
            {
              out << separator << models[m].first << " " << count[m];
              separator = ", ";
            }
          std::vector<bool> block_auto(mesh.n_blocks(), false);
          for (unsigned int c = 0; c < cell_auto.size(); ++c)
            block_auto[mesh.block_of_cell(c)] =
              block_auto[mesh.block_of_cell(c)] || cell_auto[c];
          const unsigned int n_auto =
            std::count(block_auto.begin(), block_auto.end(), true);
          if (n_auto > 0)
            out << "; " << n_auto << " of them auto";
          out << ")";
        }
      out << ", cells: " << mesh.get_triangulation().n_active_cells()
          << ", vertices: " << mesh.get_triangulation().n_vertices()
          << ", degrees of freedom: " << dof_handler.n_dofs() << " ("
          << fe->base_element(0).get_name() << ")\n"
          << "  BLAS: " << blas_description() << "\n"
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
