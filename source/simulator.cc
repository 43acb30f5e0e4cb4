// SPDX-License-Identifier: GPL-3.0-or-later

#include <deal.II/base/utilities.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_values.h>

#include <deal.II/grid/grid_tools.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/precondition.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>

#include <deal.II/numerics/data_out.h>

#include <ndda/base/utilities.h>
#include <ndda/fracture/edge_stress.h>
#include <ndda/mesh/state_transfer.h>
#include <ndda/simulator.h>

#include <filesystem>
#include <iomanip>
#include <map>
#include <sstream>

namespace ndda
{
  namespace
  {
    /** A stream buffer that writes to two buffers (console and log). */
    class TeeBuffer : public std::streambuf
    {
    public:
      TeeBuffer(std::streambuf *a, std::streambuf *b)
        : a(a)
        , b(b)
      {}

    protected:
      int
      overflow(int c) override
      {
        if (c == EOF)
          return !EOF;
        const int ra = a->sputc(c), rb = b->sputc(c);
        return (ra == EOF || rb == EOF) ? EOF : c;
      }
      int
      sync() override
      {
        return (a->pubsync() == 0 && b->pubsync() == 0) ? 0 : -1;
      }

    private:
      std::streambuf *a, *b;
    };

    /** cos and sin of a small angle, by series where that is exact. */
    std::pair<double, double>
    cos_sin(const double omega)
    {
      if (std::abs(omega) > 1e-2)
        return {std::cos(omega), std::sin(omega)};
      // Truncation below 1e-15 for |omega| <= 1e-2.
      const double w2 = omega * omega;
      return {1. - w2 / 2. * (1. - w2 / 12. * (1. - w2 / 30.)),
              omega * (1. - w2 / 6. * (1. - w2 / 20.))};
    }

    /** Rotate the 2D vector stored at dofs (i, j) by the angle omega. */
    void
    rotate_pair(Vector<double>               &v,
                const types::global_dof_index i,
                const types::global_dof_index j,
                const double                  c,
                const double                  s)
    {
      const double x = v[i], y = v[j];
      v[i] = c * x - s * y;
      v[j] = s * x + c * y;
    }
  } // namespace



  template <int dim>
  Simulator<dim>::Simulator(const std::string &parameter_file)
    : console(std::cout.rdbuf())
    , pcout(console, true)
    , timer(pcout, TimerOutput::never, TimerOutput::wall_times)
    , mapping(linear_mapping())
    , dof_handler(mesh.get_triangulation())
  {
    parameters.read_file(parameter_file, prm);
    parameters_from_file = true;
  }



  template <int dim>
  Simulator<dim>::Simulator(const parameters::Parameters &parameters,
                            const Triangulation<dim>     *triangulation)
    : parameters(parameters)
    , console(std::cout.rdbuf())
    , pcout(console, true)
    , timer(pcout, TimerOutput::never, TimerOutput::wall_times)
    , mapping(linear_mapping())
    , dof_handler(mesh.get_triangulation())
  {
    if (triangulation != nullptr)
      {
        user_triangulation = std::make_unique<Triangulation<dim>>();
        user_triangulation->copy_triangulation(*triangulation);
      }
  }



  template <int dim>
  Simulator<dim>::~Simulator()
  {
    dof_handler.clear();
    console.rdbuf(std::cout.rdbuf());
  }



  template <int dim>
  void
  Simulator<dim>::make_mesh(const Triangulation<dim> *triangulation)
  {
    const auto &geometry = parameters.geometry;
    if (triangulation != nullptr)
      mesh.build(*triangulation);
    else if (!geometry.mesh_file.empty())
      {
        const auto material_of_tag = [&](const unsigned int tag) {
          for (const auto &[t, name] : geometry.mesh_file_materials)
            if (t == tag)
              return parameters.materials.id(name,
                                             "Geometry/Mesh file materials");
          AssertThrow(geometry.mesh_file_materials.empty(),
                      ExcMessage("Geometry/Mesh file materials: the mesh "
                                 "has physical tag " +
                                 std::to_string(tag) +
                                 ", which is not listed. Give a material "
                                 "for every physical surface."));
          return tag;
        };
        mesh.read_msh(geometry.mesh_file, material_of_tag);
      }
    else
      {
        AssertThrow(!geometry.blocks.empty() || !geometry.regions.empty(),
                    ExcMessage("Geometry: the scene has no blocks. Give "
                               "'set Blocks = name' with a subsection "
                               "'name', or Regions, or a Mesh file."));
        geometry::SceneGeometry scene;
        scene.blocks    = geometry.blocks;
        scene.regions   = geometry.regions;
        scene.min_angle = geometry.min_angle;
        // Every point where something acts becomes a mesh vertex.
        auto &required = scene.required_vertices;
        for (const auto &load : parameters.loads.point_loads)
          required.push_back(load.point);
        for (const auto &load : parameters.loads.line_loads)
          {
            required.push_back(load.segment.a);
            required.push_back(load.segment.b);
          }
        for (const auto &bc : parameters.boundary_conditions.conditions)
          {
            required.insert(required.end(), bc.points.begin(), bc.points.end());
            for (const auto &s : bc.segments)
              {
                required.push_back(s.a);
                required.push_back(s.b);
              }
          }
        for (const auto &bolt : parameters.bolts.bolts)
          {
            required.push_back(bolt.first);
            required.push_back(bolt.second);
          }
        required.insert(required.end(),
                        parameters.output.measure_points.begin(),
                        parameters.output.measure_points.end());
        mesh.build(geometry::mesh_scene(scene));
      }
    for (const auto &cell : mesh.get_triangulation().active_cell_iterators())
      AssertThrow(cell->material_id() < parameters.materials.materials.size(),
                  ExcMessage(
                    "Mesh: a cell has material id " +
                    std::to_string(cell->material_id()) + ", but only " +
                    std::to_string(parameters.materials.materials.size()) +
                    " materials are declared in Materials/Names."));
  }



  template <int dim>
  void
  Simulator<dim>::setup()
  {
    TimerOutput::Scope scope(timer, "setup");
    make_mesh(user_triangulation.get());
    const auto box    = mesh.bounding_box();
    scene_half_height = 0.5 * std::max(box.second[1] - box.first[1],
                                       1e-3 * (box.second[0] - box.first[0]));

    setup_dofs();
    setup_constraints();
    setup_contacts();
    setup_fracture();
    setup_loads();
    setup_measure_points();

    // Initial state: stress and velocity per block.
    const unsigned int n_q = element_cache.n_quadrature_points();
    stress.assign(mesh.get_triangulation().n_active_cells(),
                  std::vector<SymmetricTensor<2, dim>>(n_q));
    std::vector<parameters::InitialState> block_state(mesh.n_blocks());
    const auto                           &names = mesh.get_block_names();
    for (unsigned int b = 0; b < names.size(); ++b)
      {
        for (unsigned int i = 0; i < parameters.geometry.blocks.size(); ++i)
          if (parameters.geometry.blocks[i].name == names[b])
            block_state[b] = parameters.geometry.block_states[i];
        for (unsigned int i = 0; i < parameters.geometry.regions.size(); ++i)
          if (names[b].rfind(parameters.geometry.regions[i].name + ".", 0) == 0)
            block_state[b] = parameters.geometry.region_states[i];
      }
    std::vector<std::unique_ptr<FunctionParser<dim>>> initial_velocity;
    for (const auto &state : block_state)
      initial_velocity.push_back(make_function(state.velocity, dim, false));

    const auto &fe_ref  = *fe;
    const auto  support = fe_ref.base_element(0).get_unit_support_points();
    std::vector<types::global_dof_index> dofs(fe_ref.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        const unsigned int b = mesh.block_of_cell(cell->active_cell_index());
        const auto        &s = block_state[b].stress;
        for (auto &sigma : stress[cell->active_cell_index()])
          {
            sigma[0][0] = s[0];
            sigma[1][1] = s[1];
            sigma[0][1] = s[2];
          }
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < dofs.size(); ++i)
          {
            const auto [component, base] = fe_ref.system_to_component_index(i);
            const Point<dim> x =
              mapping.transform_unit_to_real_cell(cell, support[base]);
            kinematics.velocity[dofs[i]] =
              initial_velocity[b]->value(x, component);
          }
      }

    compute_internal_force();

    time::StepController::Limits limits;
    limits.nominal_step           = parameters.control.time_step;
    limits.end_time               = parameters.control.end_time;
    limits.max_cuts               = parameters.control.max_step_cuts;
    limits.max_displacement_ratio = parameters.control.max_displacement_ratio;
    limits.max_open_close_iterations =
      parameters.contact.max_open_close_iterations;
    step_controller = time::StepController(limits);
    is_set_up       = true;
  }



  template <int dim>
  void
  Simulator<dim>::setup_dofs(const bool element_matrices)
  {
    // The element by name and what travels with it (physics/finite_element.h).
    auto element = make_element(parameters.control.finite_element);
    fe           = std::move(element.system);
    face_quadrature =
      std::make_unique<Quadrature<dim - 1>>(element.face_quadrature);
    element_cache.set_quadratures(element.cell_quadrature,
                                  element.mass_quadrature);
    n_output_subdivisions = element.n_output_subdivisions;
    dof_handler.distribute_dofs(*fe);
    cell_material.resize(mesh.get_triangulation().n_active_cells());
    for (const auto &cell : mesh.get_triangulation().active_cell_iterators())
      cell_material[cell->active_cell_index()] = cell->material_id();

    dof_map.reinit(dof_handler);

    const unsigned int n = dof_handler.n_dofs();
    displacement.reinit(n);
    kinematics.velocity.reinit(n);
    kinematics.inertia_force.reinit(n);
    internal_force.reinit(n);

    if (element_matrices)
      element_cache.update(
        dof_handler, mapping, parameters.materials, false, 0.);
    double max_modulus = 0;
    for (const auto &m : parameters.materials.materials)
      max_modulus = std::max(max_modulus, m.youngs_modulus);
    penalty_stiffness = parameters.control.penalty_factor * max_modulus *
                        parameters.materials.thickness;
    linear_solver =
      std::make_unique<LinearSolver>(parameters.control.linear_solver,
                                     parameters.control.solver_tolerance);
  }



  template <int dim>
  void
  Simulator<dim>::setup_constraints()
  {
    const NodeLocator nodes(mesh, dof_handler, mapping);
    if (parameters.control.linear_solver ==
        parameters::LinearSolverType::cg_amg)
      linear_solver->set_rigid_body_modes(nodes.support_points,
                                          nodes.component);
    boundary_constraints.setup(parameters.boundary_conditions,
                               parameters.control.constraint_method,
                               nodes);
    DynamicSparsityPattern dsp(dof_handler.n_dofs());
    DoFTools::make_sparsity_pattern(dof_handler,
                                    dsp,
                                    boundary_constraints.affine_constraints(),
                                    true);
    // Bolts couple two nodes that may lie in different blocks.
    bolts.setup(parameters.bolts, nodes);
    bolts.add_couplings(dsp);
    if (parameters.contact.enabled)
      base_sparsity.copy_from(dsp);
    reinit_matrices(dsp);
    pattern_couplings.clear();
  }



  template <int dim>
  void
  Simulator<dim>::reinit_matrices(DynamicSparsityPattern &dsp)
  {
    boundary_constraints.affine_constraints().condense(dsp);
    sparsity_pattern.copy_from(dsp);
    stiffness_matrix.reinit(sparsity_pattern);
    mass_matrix.reinit(sparsity_pattern);
    damping_matrix.reinit(sparsity_pattern);
    system_matrix.reinit(sparsity_pattern);
    condensed_matrix.reinit(sparsity_pattern);
  }



  template <int dim>
  void
  Simulator<dim>::setup_contacts()
  {
    if (!parameters.contact.enabled)
      return;
    const auto &materials   = parameters.materials;
    double      max_modulus = 0;
    for (const auto &m : materials.materials)
      max_modulus = std::max(max_modulus, m.youngs_modulus);

    // The friction coefficient of each boundary edge's side: its
    // material's joint friction angle, or the scene's joint angle.
    const auto edges = boundary_edges(mesh.get_block_mesh());
    // The edges index the triangles of the block mesh, which are the
    // active cells of the triangulation, vertex order kept.
    {
      std::vector<typename Triangulation<dim>::active_cell_iterator> cells;
      for (const auto &cell : mesh.get_triangulation().active_cell_iterators())
        cells.push_back(cell);
      for (const auto &e : edges)
        AssertThrow(cells[e.cell]->vertex_index(e.local_vertex) == e.v0 &&
                      cells[e.cell]->vertex_index((e.local_vertex + 1) % 3) ==
                        e.v1,
                    ExcInternalError());
    }
    std::vector<double> edge_friction(edges.size());
    for (unsigned int e = 0; e < edges.size(); ++e)
      {
        const auto  &m     = materials.materials[cell_material[edges[e].cell]];
        const double angle = m.joint_friction_angle >= 0. ?
                               m.joint_friction_angle :
                               materials.joint.friction_angle;
        edge_friction[e]   = std::tan(angle * numbers::PI / 180.);
      }

    contact::DofAccess access;
    access.fe          = fe.get();
    access.cell_dofs   = &dof_map.cell_dofs;
    access.component   = &dof_map.local_component;
    access.vertex_dofs = &dof_map.vertex_dofs;

    // Shi's detection distance: twice the largest displacement a step may
    // have, so every contact a step can close is a candidate of that step.
    contact_threshold =
      2. * parameters.control.max_displacement_ratio * scene_half_height;
    penetration_tolerance =
      parameters.contact.max_penetration_ratio * scene_half_height;

    contact::ContactSettings settings;
    settings.normal_stiffness =
      parameters.contact.penalty_factor * max_modulus * materials.thickness;
    settings.shear_ratio          = parameters.contact.shear_stiffness_ratio;
    settings.vertex_vertex_method = parameters.contact.vertex_vertex_method;
    settings.state_tolerance      = 1e-9 * penetration_tolerance;
    settings.ignore_depth         = penetration_tolerance;
    settings.bond_tension =
      materials.joint.tensile_strength * materials.thickness;
    settings.bond_cohesion = materials.joint.cohesion * materials.thickness;
    settings.law           = parameters.contact.law;
    settings.average_start_and_end =
      parameters.control.time_integrator->averages_contact_forces();
    contacts.initialize(edges, edge_friction, access, settings);
  }



  template <int dim>
  void
  Simulator<dim>::update_sparsity_for_contacts()
  {
    // The pattern holds the couplings of every candidate contact of the
    // step and those of earlier steps: it (and every matrix on it) is
    // rebuilt only when a coupling is missing, with the union of both
    // sets, so that candidates which come and go near the detection
    // distance do not change it and the direct solver keeps its symbolic
    // analysis (UMFPACK) or its pivot order (KLU). When the pattern holds
    // more than twice the couplings in use, it is rebuilt with the
    // present ones only.
    const auto &couplings = contacts.get_couplings();
    if (std::includes(pattern_couplings.begin(),
                      pattern_couplings.end(),
                      couplings.begin(),
                      couplings.end()) &&
        pattern_couplings.size() <= 2 * couplings.size() + 16)
      return;
    std::vector<std::pair<unsigned int, unsigned int>> merged;
    std::set_union(pattern_couplings.begin(),
                   pattern_couplings.end(),
                   couplings.begin(),
                   couplings.end(),
                   std::back_inserter(merged));
    if (merged.size() > 2 * couplings.size() + 16)
      merged = couplings;
    TimerOutput::Scope                   scope(timer, "sparsity");
    DynamicSparsityPattern               dsp(base_sparsity.n_rows());
    std::vector<types::global_dof_index> row;
    for (types::global_dof_index i = 0; i < base_sparsity.n_rows(); ++i)
      {
        row.clear();
        for (auto entry = base_sparsity.begin(i); entry != base_sparsity.end(i);
             ++entry)
          row.push_back(entry->column());
        dsp.add_entries(i, row.begin(), row.end());
      }
    const unsigned int n_cell_dofs = fe->n_dofs_per_cell();
    for (const auto &[vertex, cell] : merged)
      for (const auto i : dof_map.vertex_dofs[vertex])
        for (unsigned int k = 0; k < n_cell_dofs; ++k)
          {
            const auto j = dof_map.cell_dofs[cell * n_cell_dofs + k];
            dsp.add(i, j);
            dsp.add(j, i);
          }
    reinit_matrices(dsp);
    pattern_couplings.swap(merged);
    assemble_global_matrices();
  }



  template <int dim>
  void
  Simulator<dim>::setup_loads()
  {
    loads.setup(parameters.loads, mesh, dof_handler, dof_map);
    loads.update_faces(dof_handler,
                       mapping,
                       *face_quadrature,
                       parameters.materials.thickness);
  }



  template <int dim>
  void
  Simulator<dim>::setup_measure_points()
  {
    measure_points.clear();
    for (const auto &p : parameters.output.measure_points)
      measure_points.push_back(
        make_point_evaluator(mesh, *fe, dof_map, p, "Output/Measure points"));
    measure_histories.assign(measure_points.size(), {});
  }



  template <int dim>
  void
  Simulator<dim>::assemble_global_matrices()
  {
    stiffness_matrix                            = 0;
    mass_matrix                                 = 0;
    damping_matrix                              = 0;
    has_damping                                 = false;
    const unsigned int                   n_dofs = fe->n_dofs_per_cell();
    std::vector<types::global_dof_index> dofs(n_dofs);
    for (unsigned int c = 0; c < dof_map.cell_dofs.size() / n_dofs; ++c)
      {
        const auto &data = element_cache[c];
        std::copy(&dof_map.cell_dofs[c * n_dofs],
                  &dof_map.cell_dofs[c * n_dofs] + n_dofs,
                  dofs.begin());
        stiffness_matrix.add(dofs, data.stiffness);
        mass_matrix.add(dofs, data.mass);
        if (data.viscosity_over_density > 0)
          {
            has_damping = true;
            for (unsigned int i = 0; i < dofs.size(); ++i)
              for (unsigned int j = 0; j < dofs.size(); ++j)
                damping_matrix.add(dofs[i],
                                   dofs[j],
                                   data.viscosity_over_density *
                                     data.mass(i, j));
          }
      }

    bolts.add_stiffness(displacement, stiffness_matrix);
    matrices_changed = true;
  }



  template <int dim>
  void
  Simulator<dim>::compute_internal_force()
  {
    // f_int = sum over cells of t * int B^T sigma (thesis 3.25 with the
    // accumulated stress in place of the initial stress).
    // Computed from the stresses every step (not updated by K d and
    // turned with the spin), so that it is self-equilibrated in every
    // cell: turning nodal forces by nodal spins that differ from node to
    // node would leave a net force on a free, vibrating block.
    //
    // The strain energy is the state function sum t int sigma : S : sigma
    // / 2 (S = C^-1) less its initial value; unlike the accumulated work
    // d . f_int, it does not drift when stresses are turned with the spin.
    internal_force            = 0;
    const unsigned int n_dofs = fe->n_dofs_per_cell();
    const unsigned int n_q    = element_cache.n_quadrature_points();
    std::vector<SymmetricTensor<4, dim>> compliance;
    for (const auto &C : element_cache.get_elasticity())
      compliance.push_back(invert(C));
    double energy = 0;
    for (unsigned int c = 0; c < dof_map.cell_dofs.size() / n_dofs; ++c)
      {
        const auto        &data     = element_cache[c];
        const auto        *dofs     = &dof_map.cell_dofs[c * n_dofs];
        const unsigned int material = cell_material[c];
        for (unsigned int q = 0; q < n_q; ++q)
          {
            const auto &sigma = stress[c][q];
            for (unsigned int i = 0; i < n_dofs; ++i)
              internal_force[dofs[i]] +=
                (data.strain[q * n_dofs + i] * sigma) * data.weight[q];
            energy +=
              0.5 * (sigma * (compliance[material] * sigma)) * data.weight[q];
          }
      }
    if (!initial_strain_energy_known)
      {
        initial_strain_energy       = energy;
        initial_strain_energy_known = true;
      }
    stored_strain_energy = energy - initial_strain_energy;
    // Bolts pull their anchors towards each other with their spring force.
    bolts.add_internal_force(displacement, internal_force);
  }



  template <int dim>
  void
  Simulator<dim>::assemble_external_force(const double    t,
                                          Vector<double> &force) const
  {
    force.reinit(dof_handler.n_dofs());
    loads.add(t, force);
    // Bolt pretension pulls the anchors together.
    bolts.add_pretension(displacement, force);
  }



  template <int dim>
  void
  Simulator<dim>::build_element_matrices(const bool only_moved_cells)
  {
    TimerOutput::Scope scope(timer, "element matrices");
    const double       tolerance = parameters.control.matrix_update_tolerance;
    // The first step uses the element matrices that setup() computed (it
    // needed them for the initial internal force); later steps recompute
    // those of the cells that moved.
    if (only_moved_cells)
      {
        const unsigned int n_computed =
          element_cache.update(dof_handler,
                               mapping,
                               parameters.materials,
                               tolerance > 0.,
                               tolerance);
        if (n_computed == 0)
          return;
      }
    ++n_matrix_rebuilds;
    assemble_global_matrices();
    loads.update_gravity(mass_matrix, dof_map);
    compute_internal_force();
    if (only_moved_cells)
      loads.update_faces(dof_handler,
                         mapping,
                         *face_quadrature,
                         parameters.materials.thickness);
  }



  template <int dim>
  void
  Simulator<dim>::assemble_system_matrix(const double dt)
  {
    TimerOutput::Scope scope(timer, "system matrix");
    const auto        &control    = parameters.control;
    const auto        &integrator = *control.time_integrator;
    const double       c_mass     = integrator.mass_coefficient(dt);
    system_matrix.copy_from(stiffness_matrix);
    if (c_mass != 0.)
      system_matrix.add(c_mass, mass_matrix);
    if (has_damping)
      system_matrix.add(integrator.damping_coefficient(dt), damping_matrix);
    if (!boundary_constraints.exact())
      boundary_constraints.add_penalty_springs(penalty_stiffness,
                                               system_matrix);
    assembled_dt     = dt;
    matrices_changed = false;
    base_factorized  = false;
  }



  template <int dim>
  void
  Simulator<dim>::factorize(const bool with_contacts)
  {
    // condensed_matrix holds the condensed system matrix, with the contact
    // springs already added if with_contacts.
    TimerOutput::Scope scope(timer, "factorize");
    linear_solver->factorize(condensed_matrix);
    base_factorized = !with_contacts;
  }



  template <int dim>
  void
  Simulator<dim>::compute_initial_acceleration()
  {
    // Newmark needs the acceleration at t = 0: M a0 = f_ext(0) - f_int, with
    // zero acceleration at constrained dofs.
    Vector<double> rhs;
    assemble_external_force(time, rhs);
    rhs -= internal_force;
    SparseMatrix<double> m(sparsity_pattern);
    m.copy_from(mass_matrix);
    const auto &constraints = boundary_constraints.affine_constraints();
    if (!boundary_constraints.exact())
      for (const auto &nc : boundary_constraints.constrained_nodes())
        for (const auto dof : nc.dofs)
          {
            rhs[dof] = 0;
            for (auto entry = m.begin(dof); entry != m.end(dof); ++entry)
              entry->value() = (entry->column() == dof ? 1. : 0.);
          }
    constraints.condense(m);
    constraints.condense(rhs);
    // The consistent mass matrix is well conditioned (its condition number
    // does not grow with refinement): Jacobi-preconditioned CG needs a few
    // dozen iterations, far less than a factorization.
    Vector<double> acceleration(rhs.size());
    if (rhs.l2_norm() > 0)
      {
        SolverControl            control(1000, 1e-14 * rhs.l2_norm());
        SolverCG<Vector<double>> cg(control);
        PreconditionJacobi<SparseMatrix<double>> jacobi;
        jacobi.initialize(m);
        cg.solve(m, acceleration, rhs, jacobi);
      }
    constraints.distribute(acceleration);
    mass_matrix.vmult(kinematics.inertia_force, acceleration);
  }



  template <int dim>
  time::AttemptResult
  Simulator<dim>::try_time_step(const double dt, Vector<double> &d)
  {
    const auto &control    = parameters.control;
    const auto &integrator = *control.time_integrator;
    const bool  exact =
      control.constraint_method == parameters::ConstraintMethod::exact;
    const bool with_contact = parameters.contact.enabled;

    if (matrices_changed || dt != assembled_dt)
      assemble_system_matrix(dt);

    // Right-hand side at the end of the step (thesis 3.15):
    // f_ext(t1) - f_int + inertia terms of the integrator.
    Vector<double> rhs;
    {
      TimerOutput::Scope scope(timer, "solve");
      assemble_external_force(time + dt, step_external_force);
      rhs = step_external_force;
      rhs -= internal_force;
      integrator.add_inertia_terms(mass_matrix, kinematics, dt, rhs);
    }

    Vector<double> prescribed(dof_handler.n_dofs());
    boundary_constraints.prescribed_increment(time,
                                              dt,
                                              displacement,
                                              prescribed);
    if (!exact)
      boundary_constraints.add_penalty_forces(penalty_stiffness,
                                              prescribed,
                                              rhs);
    const auto &constraints = boundary_constraints.affine_constraints();
    d.reinit(dof_handler.n_dofs());

    // The open-close iteration (thesis 2.3.13; DESIGN decision 5): solve
    // with the springs of the present contact states, classify the
    // contacts from the solution, and solve again until no state changes.
    // The element part of the matrix is kept; only contact springs change
    // between iterations.
    const unsigned int max_iterations =
      with_contact ? parameters.contact.max_open_close_iterations : 1;
    bool settled = false;
    for (unsigned int iteration = 0; iteration < max_iterations; ++iteration)
      {
        const bool     springs = with_contact && contacts.has_springs();
        Vector<double> b(rhs);
        // Newmark averages the forces at the step's start and end. A
        // contact that opens in this step would keep half of its start
        // force for the whole step and hand the body the energy
        // F0 g1 / 2 (g1 the gap it opens): only contacts closed at both
        // ends enter the average (doc/contact.md).
        inertia_correction.reinit(dof_handler.n_dofs());
        if (with_contact && integrator.averages_contact_forces())
          {
            contacts.newmark_correction(inertia_correction);
            b += inertia_correction;
          }
        if (springs)
          {
            TimerOutput::Scope scope(timer, "contact assembly");
            condensed_matrix.copy_from(system_matrix);
            contacts.assemble(condensed_matrix, b);
          }
        else if (!base_factorized)
          condensed_matrix.copy_from(system_matrix);

        TimerOutput::Scope scope(timer, "solve");
        if (exact)
          {
            // d = d_h + d_g: d_g carries the prescribed values, d_h
            // satisfies the homogeneous constraints.
            if (!boundary_constraints.constrained_nodes().empty())
              {
                Vector<double> tmp(dof_handler.n_dofs());
                if (springs || !base_factorized)
                  condensed_matrix.vmult(tmp, prescribed);
                else
                  system_matrix.vmult(tmp, prescribed);
                b -= tmp;
              }
            constraints.condense(b);
          }
        if (springs || !base_factorized)
          {
            constraints.condense(condensed_matrix);
            // A changed system: try the last factorization as GMRES
            // preconditioner first (only contact springs or the contact
            // geometry differ), factorize if it does not serve.
            last_solver_iterations =
              with_contact && !refactorize_next ?
                linear_solver->solve_with_earlier_factorization(
                  condensed_matrix,
                  d,
                  b,
                  parameters.contact.reuse_iterations,
                  1e-12) :
                0;
            refactorize_next = false;
            if (last_solver_iterations == 0)
              {
                factorize(springs);
                last_solver_iterations = linear_solver->solve(d, b);
              }
            else if (2 * last_solver_iterations >
                     parameters.contact.reuse_iterations)
              // Converging slowly: the factorization has aged.
              refactorize_next = true;
          }
        else
          last_solver_iterations = linear_solver->solve(d, b);
        if (exact)
          {
            constraints.distribute(d);
            d += prescribed;
          }
        if (with_contact)
          contacts.count_iteration();
        if (!with_contact || !contacts.update_states(d))
          {
            settled = true;
            break;
          }
      }
    if (!settled)
      return time::AttemptResult::not_settled;

    // DDA step control: the largest nodal displacement must stay below the
    // allowed fraction of half the scene height.
    max_increment = 0;
    for (const auto &dofs : dof_map.vertex_dofs)
      max_increment =
        std::max(max_increment,
                 d[dofs[0]] * d[dofs[0]] + d[dofs[1]] * d[dofs[1]]);
    max_increment = std::sqrt(max_increment);
    if (max_increment > control.max_displacement_ratio * scene_half_height)
      return time::AttemptResult::too_large;

    // A cell that the increment turns inside out: no strain measure of the
    // linear update holds there (its strain energy changes sign). Only a
    // diverging motion or a step far too large does this; cut the step.
    {
      const auto &block_mesh = mesh.get_block_mesh();
      for (const auto &t : block_mesh.triangles)
        {
          std::array<Point<dim>, 3> now, next;
          for (unsigned int k = 0; k < 3; ++k)
            {
              now[k] = next[k] = block_mesh.vertices[t[k]];
              for (unsigned int c = 0; c < dim; ++c)
                next[k][c] += d[dof_map.vertex_dofs[t[k]][c]];
            }
          const auto twice_area = [](const std::array<Point<dim>, 3> &p) {
            return (p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) -
                   (p[1][1] - p[0][1]) * (p[2][0] - p[0][0]);
          };
          if (twice_area(now) * twice_area(next) <= 0)
            return time::AttemptResult::inverted;
        }
    }

    if (with_contact &&
        parameters.contact.penalty_method ==
          parameters::PenaltyMethod::automatic &&
        contacts.max_penetration(d) > penetration_tolerance)
      {
        contacts.set_normal_stiffness(2. *
                                      contacts.get_settings().normal_stiffness);
        return time::AttemptResult::penalty_raised;
      }
    return time::AttemptResult::accepted;
  }



  template <int dim>
  void
  Simulator<dim>::commit_step(const Vector<double> &d, const double dt)
  {
    TimerOutput::Scope scope(timer, "update");
    if (parameters.contact.enabled)
      contacts.end_step(d);

    // Velocity and acceleration at the end of the step.
    parameters.control.time_integrator->update(
      d, dt, mass_matrix, inertia_correction, kinematics);

    // Objective update: first turn the state of the step's start by the
    // increment's rotation, then add the increment's stress.
    if (parameters.control.rotate_with_spin)
      rotate_velocities(d);
    for (unsigned int c = 0; c < stress.size(); ++c)
      advance_cell_stress(c, d, stress[c]);

    bolts.update(displacement, d);

    // Work of the loads over the step, by the trapezoidal rule.
    load_work += 0.5 * (external_force * d + step_external_force * d);
    external_force = step_external_force;

    // The internal force of the new stresses, and the strain energy they
    // hold.
    compute_internal_force();

    displacement += d;
    move_mesh(d);
    time += dt;
  }



  template <int dim>
  std::pair<double, double>
  Simulator<dim>::cell_rotation(const unsigned int    c,
                                const Vector<double> &d) const
  {
    const unsigned int n_dofs = fe->n_dofs_per_cell();
    const unsigned int n_q    = element_cache.n_quadrature_points();
    const auto        &data   = element_cache[c];
    const auto        *dofs   = &dof_map.cell_dofs[c * n_dofs];
    double             omega = 0, area = 0;
    for (unsigned int q = 0; q < n_q; ++q)
      {
        for (unsigned int i = 0; i < n_dofs; ++i)
          omega += d[dofs[i]] * data.spin[q * n_dofs + i] * data.weight[q];
        area += data.weight[q];
      }
    return {omega, area};
  }



  template <int dim>
  void
  Simulator<dim>::advance_cell_stress(
    const unsigned int                    c,
    const Vector<double>                 &d,
    std::vector<SymmetricTensor<2, dim>> &sigma) const
  {
    // The small-rotation update moves points along straight lines; turn
    // each cell's stress by the cell's rotation in the increment
    // (Jaumann-like, sigma <- R sigma R^T) before adding the increment's
    // stress, sigma += C eps(d). See doc/theory.md.
    if (parameters.control.rotate_with_spin)
      {
        const auto [rotation, area] = cell_rotation(c, d);
        const double omega          = rotation / area;
        if (omega != 0.)
          {
            const auto [cs, sn] = cos_sin(omega);
            for (auto &s : sigma)
              {
                const double xx = s[0][0], yy = s[1][1], xy = s[0][1];
                s[0][0] = cs * cs * xx - 2 * cs * sn * xy + sn * sn * yy;
                s[1][1] = sn * sn * xx + 2 * cs * sn * xy + cs * cs * yy;
                s[0][1] = cs * sn * (xx - yy) + (cs * cs - sn * sn) * xy;
              }
          }
      }
    const unsigned int n_dofs = fe->n_dofs_per_cell();
    const auto        &data   = element_cache[c];
    const auto        *dofs   = &dof_map.cell_dofs[c * n_dofs];
    const auto        &C = element_cache.get_elasticity()[cell_material[c]];
    for (unsigned int q = 0; q < sigma.size(); ++q)
      {
        SymmetricTensor<2, dim> eps;
        for (unsigned int i = 0; i < n_dofs; ++i)
          eps += d[dofs[i]] * data.strain[q * n_dofs + i];
        sigma[q] += C * eps;
      }
  }



  template <int dim>
  void
  Simulator<dim>::rotate_velocities(const Vector<double> &d)
  {
    // The small-rotation update moves points along straight lines: a
    // spinning block would not turn its velocity. As DDA does with its
    // block rotation, turn the velocity (and inertia force) of each block
    // relative to its centre of mass by the block's rotation in the
    // increment; the cells' stresses turn in advance_cell_stress().
    // Only the part relative to the centre of mass turns: a block that
    // falls while it vibrates (its spin oscillating) keeps its momentum,
    // where turning whole nodal velocities by nodal spins made it drift
    // sideways by metres. See doc/theory.md.
    const unsigned int        n_dofs   = fe->n_dofs_per_cell();
    const unsigned int        n_blocks = mesh.n_blocks();
    std::vector<double>       block_spin(n_blocks), block_area(n_blocks);
    std::vector<unsigned int> node_block(dof_map.node_dofs.size(),
                                         numbers::invalid_unsigned_int);
    for (unsigned int c = 0; c < dof_map.cell_dofs.size() / n_dofs; ++c)
      {
        const auto [omega, area] = cell_rotation(c, d);
        const unsigned int b     = mesh.block_of_cell(c);
        block_spin[b] += omega;
        block_area[b] += area;
        const auto *dofs = &dof_map.cell_dofs[c * n_dofs];
        for (unsigned int i = 0; i < n_dofs; ++i)
          node_block[dof_map.dof_to_node[dofs[i]]] = b;
      }

    // Centre-of-mass velocity and acceleration of each block, with the
    // row sums of the mass matrix as nodal masses (1^T M v is the momentum
    // for the consistent mass too).
    std::vector<double>         block_mass(n_blocks);
    std::vector<Tensor<1, dim>> block_velocity(n_blocks), block_force(n_blocks);
    std::vector<double>         node_mass(dof_map.node_dofs.size());
    for (unsigned int n = 0; n < dof_map.node_dofs.size(); ++n)
      {
        const unsigned int b = node_block[n];
        if (b == numbers::invalid_unsigned_int)
          continue;
        double m = 0;
        for (auto entry = mass_matrix.begin(dof_map.node_dofs[n][0]);
             entry != mass_matrix.end(dof_map.node_dofs[n][0]);
             ++entry)
          m += entry->value();
        node_mass[n] = m;
        block_mass[b] += m;
        for (unsigned int k = 0; k < dim; ++k)
          {
            block_velocity[b][k] +=
              m * kinematics.velocity[dof_map.node_dofs[n][k]];
            block_force[b][k] +=
              kinematics.inertia_force[dof_map.node_dofs[n][k]];
          }
      }
    for (unsigned int b = 0; b < n_blocks; ++b)
      if (block_mass[b] > 0.)
        {
          block_velocity[b] /= block_mass[b];
          block_force[b] /= block_mass[b]; // per unit mass
          block_spin[b] /= block_area[b];
        }

    for (unsigned int n = 0; n < dof_map.node_dofs.size(); ++n)
      {
        const unsigned int b = node_block[n];
        if (b == numbers::invalid_unsigned_int || block_spin[b] == 0. ||
            block_mass[b] <= 0.)
          continue;
        const auto [cs, sn] = cos_sin(block_spin[b]);
        const auto [i, j]   = dof_map.node_dofs[n];
        for (unsigned int k = 0; k < dim; ++k)
          {
            kinematics.velocity[dof_map.node_dofs[n][k]] -=
              block_velocity[b][k];
            kinematics.inertia_force[dof_map.node_dofs[n][k]] -=
              node_mass[n] * block_force[b][k];
          }
        rotate_pair(kinematics.velocity, i, j, cs, sn);
        rotate_pair(kinematics.inertia_force, i, j, cs, sn);
        for (unsigned int k = 0; k < dim; ++k)
          {
            kinematics.velocity[dof_map.node_dofs[n][k]] +=
              block_velocity[b][k];
            kinematics.inertia_force[dof_map.node_dofs[n][k]] +=
              node_mass[n] * block_force[b][k];
          }
      }
  }



  template <int dim>
  void
  Simulator<dim>::move_mesh(const Vector<double> &d)
  {
    std::vector<Tensor<1, dim>> vertex_increment(dof_map.vertex_dofs.size());
    for (unsigned int v = 0; v < dof_map.vertex_dofs.size(); ++v)
      for (unsigned int c = 0; c < dim; ++c)
        vertex_increment[v][c] = d[dof_map.vertex_dofs[v][c]];
    mesh.move_vertices(vertex_increment);
  }



  template <int dim>
  void
  Simulator<dim>::setup_fracture()
  {
    fracture_edges.clear();
    fracture_strength.clear();
    const auto &materials = parameters.materials.materials;
    bool        any       = false;
    for (const auto &m : materials)
      any = any || m.fracture;
    fracture_enabled = any;
    if (!any)
      return;
    const auto &block_mesh = mesh.get_block_mesh();
    for (const auto &edge :
         fracture::find_interior_edges(block_mesh.triangles,
                                       block_mesh.vertices.size()))
      {
        if (mesh.is_cracked(edge.vertices[0], edge.vertices[1]))
          continue; // a closed crack (both tips inside a block)
        const auto &m0 = materials[cell_material[edge.cells[0]]];
        const auto &m1 = materials[cell_material[edge.cells[1]]];
        if (!m0.fracture || !m1.fracture)
          continue;
        fracture::Strength strength;
        strength.cohesion = std::min(m0.cohesion, m1.cohesion);
        strength.friction_angle =
          std::min(m0.friction_angle, m1.friction_angle) * numbers::PI / 180.;
        strength.tensile_strength =
          std::min(m0.tensile_strength, m1.tensile_strength);
        fracture_edges.push_back(edge);
        fracture_strength.push_back(strength);
      }
  }



  template <int dim>
  std::vector<SymmetricTensor<2, dim>>
  Simulator<dim>::cell_mean_stresses() const
  {
    std::vector<SymmetricTensor<2, dim>> mean(stress.size());
    for (unsigned int c = 0; c < stress.size(); ++c)
      mean[c] = mean_cell_stress(c);
    return mean;
  }



  template <int dim>
  std::vector<std::array<unsigned int, 2>>
  Simulator<dim>::check_fracture(const Vector<double> &d, const double dt)
  {
    static_assert(dim == 2, "fracture is two-dimensional");
    TimerOutput::Scope  scope(timer, "fracture check");
    const auto         &block_mesh = mesh.get_block_mesh();
    std::vector<double> area(stress.size());
    for (unsigned int c = 0; c < stress.size(); ++c)
      for (const double w : element_cache[c].weight)
        area[c] += w;
    // The step's trial end: vertices moved by the increment, stresses
    // advanced by it (as commit_step() will do, if no edge cracks).
    std::vector<Point<dim>> end_vertices = block_mesh.vertices;
    for (unsigned int v = 0; v < end_vertices.size(); ++v)
      for (unsigned int c = 0; c < dim; ++c)
        end_vertices[v][c] += d[dof_map.vertex_dofs[v][c]];
    std::vector<SymmetricTensor<2, dim>> end_stresses(stress.size());
    std::vector<SymmetricTensor<2, dim>> sigma;
    for (unsigned int c = 0; c < stress.size(); ++c)
      {
        sigma = stress[c];
        advance_cell_stress(c, d, sigma);
        end_stresses[c] = mean_stress(c, sigma);
      }
    const auto method = parameters.fracture.edge_stress_method;
    const auto start  = fracture::edge_states(fracture_edges,
                                             block_mesh.vertices,
                                             block_mesh.triangles,
                                             cell_mean_stresses(),
                                             area,
                                             method);
    const auto end    = fracture::edge_states(fracture_edges,
                                           end_vertices,
                                           block_mesh.triangles,
                                           end_stresses,
                                           area,
                                           method);
    const bool first_record_done =
      first_edge_failure.mode != fracture::FailureMode::none;
    n_failing_edges = 0;
    // The edges that fail, with their failure times (fractions of the
    // step); the earliest ones, within the crack window, crack first.
    std::vector<std::pair<double, unsigned int>> failing;
    for (unsigned int e = 0; e < fracture_edges.size(); ++e)
      {
        const fracture::EdgeFailure failure =
          parameters.fracture.criterion->failure_in_step(start[e],
                                                         end[e],
                                                         fracture_strength[e]);
        if (!failure.fails())
          continue;
        ++n_failing_edges;
        failing.emplace_back(failure.time, e);
        const double t = time + failure.time * dt;
        // The first check that finds failing edges keeps the earliest of
        // them; the re-solves after a crack do not change the record (a
        // crack can make another edge fail earlier within the same step).
        if (!first_record_done &&
            (first_edge_failure.mode == fracture::FailureMode::none ||
             t < first_edge_failure.time))
          {
            const auto &v           = fracture_edges[e].vertices;
            first_edge_failure.mode = failure.mode;
            first_edge_failure.time = t;
            first_edge_failure.location =
              Point<dim>(0.5 * (end_vertices[v[0]] + end_vertices[v[1]]));
          }
      }
    std::vector<std::array<unsigned int, 2>> edges;
    if (failing.empty())
      return edges;
    std::sort(failing.begin(), failing.end());
    const double last =
      failing.front().first + parameters.fracture.crack_window + 1e-12;
    for (const auto &[t, e] : failing)
      if (t <= last)
        edges.push_back(fracture_edges[e].vertices);
    return edges;
  }



  template <int dim>
  void
  Simulator<dim>::crack_edges(
    const std::vector<std::array<unsigned int, 2>> &edges)
  {
    TimerOutput::Scope scope(timer, "crack");
    // What the old dof numbering carries, before crack() empties the
    // DoFHandler: dof vectors by cell, the acceleration as M a over the
    // lumped mass (a force vector must not be copied to both sides of a
    // split node).
    const std::vector<types::global_dof_index> old_cell_dofs =
      dof_map.cell_dofs;
    const auto lumped_mass = [this]() {
      Vector<double> m(mass_matrix.m());
      for (unsigned int i = 0; i < m.size(); ++i)
        for (auto entry = mass_matrix.begin(i); entry != mass_matrix.end(i);
             ++entry)
          m[i] += entry->value();
      return m;
    };
    const Vector<double> old_mass = lumped_mass();
    Vector<double>       acceleration(kinematics.inertia_force);
    for (unsigned int i = 0; i < acceleration.size(); ++i)
      if (old_mass[i] > 0.)
        acceleration[i] /= old_mass[i];
    const Vector<double>          old_displacement(displacement);
    const Vector<double>          old_velocity(kinematics.velocity);
    const std::vector<double>     bolt_forces = bolts.axial_forces();
    const contact::ContactHandler old_contacts(contacts);

    mesh.crack(edges);
    n_cracked_edges += edges.size();

    setup_dofs(false);
    const auto transfer = [&](const Vector<double> &old, Vector<double> &now) {
      now.reinit(dof_handler.n_dofs());
      state_transfer::transfer_dof_values(old_cell_dofs,
                                          old,
                                          dof_map.cell_dofs,
                                          now);
    };
    transfer(old_displacement, displacement);
    transfer(old_velocity, kinematics.velocity);
    Vector<double> new_acceleration;
    transfer(acceleration, new_acceleration);
    // Constraints, loads and measure points are found by position on the
    // scene's initial geometry: set them up with the mesh moved back
    // there, then move it forward again.
    std::vector<Tensor<1, dim>> u(dof_map.vertex_dofs.size());
    for (unsigned int v = 0; v < dof_map.vertex_dofs.size(); ++v)
      for (unsigned int c = 0; c < dim; ++c)
        u[v][c] = -displacement[dof_map.vertex_dofs[v][c]];
    mesh.move_vertices(u);
    setup_constraints();
    bolts.set_axial_forces(bolt_forces);
    setup_loads();
    measure_points.clear(); // their histories stay
    for (const auto &p : parameters.output.measure_points)
      measure_points.push_back(
        make_point_evaluator(mesh, *fe, dof_map, p, "Output/Measure points"));
    for (auto &x : u)
      x *= -1.;
    mesh.move_vertices(u);

    setup_contacts();
    if (parameters.contact.enabled)
      contacts.carry_memory_from(old_contacts);
    setup_fracture();

    // A crack changes no cell's shape (cells keep their index, vertex
    // order and geometry; only dof numbers change): element matrices are
    // recomputed only for cells that moved beyond the tolerance since
    // their last computation, as in any step. Then global matrices,
    // gravity, internal force, loaded faces, and M a on the new mesh.
    const double tolerance = parameters.control.matrix_update_tolerance;
    element_cache.update(
      dof_handler, mapping, parameters.materials, tolerance > 0., tolerance);
    build_element_matrices(false);
    loads.update_faces(dof_handler,
                       mapping,
                       *face_quadrature,
                       parameters.materials.thickness);
    kinematics.inertia_force = lumped_mass();
    kinematics.inertia_force.scale(new_acceleration);
    external_force.reinit(dof_handler.n_dofs());
    assemble_external_force(time, external_force);
    assembled_dt     = -1;
    base_factorized  = false;
    refactorize_next = false;
  }



  template <int dim>
  SymmetricTensor<2, dim>
  Simulator<dim>::mean_cell_stress(const unsigned int cell) const
  {
    return mean_stress(cell, stress[cell]);
  }



  template <int dim>
  SymmetricTensor<2, dim>
  Simulator<dim>::mean_stress(
    const unsigned int                          cell,
    const std::vector<SymmetricTensor<2, dim>> &sigma) const
  {
    const auto             &data = element_cache[cell];
    SymmetricTensor<2, dim> mean;
    double                  area = 0;
    for (unsigned int q = 0; q < sigma.size(); ++q)
      {
        mean += data.weight[q] * sigma[q];
        area += data.weight[q];
      }
    return mean / area;
  }



  template <int dim>
  double
  Simulator<dim>::kinetic_energy() const
  {
    return 0.5 * mass_matrix.matrix_norm_square(kinematics.velocity);
  }



  template <int dim>
  void
  Simulator<dim>::record_measure_points()
  {
    for (unsigned int m = 0; m < measure_points.size(); ++m)
      {
        const auto   &e = measure_points[m];
        MeasureSample sample;
        sample.time = time;
        for (unsigned int i = 0; i < e.dofs.size(); ++i)
          {
            sample.displacement[e.component[i]] +=
              e.shape_values[i] * displacement[e.dofs[i]];
            sample.velocity[e.component[i]] +=
              e.shape_values[i] * kinematics.velocity[e.dofs[i]];
          }
        sample.stress = mean_cell_stress(e.cell);
        measure_histories[m].push_back(sample);
      }
  }



  template <int dim>
  void
  Simulator<dim>::prepare_step()
  {
    if (step_number > 0)
      {
        build_element_matrices(true);
        return;
      }
    build_element_matrices(false);
    if (parameters.control.time_integrator->needs_initial_acceleration())
      compute_initial_acceleration();
    if (measure_histories.size() > 0 && measure_histories[0].empty())
      record_measure_points();
    assemble_external_force(time, external_force);
    initial_kinetic_energy = kinetic_energy();
  }



  template <int dim>
  double
  Simulator<dim>::solve_step(Vector<double> &d)
  {
    // Contacts are detected once per step, on the geometry of its start;
    // the detection distance covers every step size the cuts may try.
    if (parameters.contact.enabled)
      {
        {
          TimerOutput::Scope scope(timer, "contact detection");
          contacts.begin_step(mesh.get_block_mesh().vertices,
                              contact_threshold);
        }
        update_sparsity_for_contacts();
      }
    double              dt = step_controller.attempt_size(time);
    time::AttemptResult result;
    while ((result = try_time_step(dt, d)) != time::AttemptResult::accepted)
      {
        if (parameters.contact.enabled)
          contacts.restart_step();
        dt = step_controller.after_failure(result, dt, max_increment);
      }
    return dt;
  }



  template <int dim>
  void
  Simulator<dim>::do_time_step()
  {
    if (!is_set_up)
      setup();
    Timer wall;
    prepare_step();
    step_controller.begin_step(step_number + 1, time);

    // The crack sequence (thesis 5.4): solve the step; if edges fail
    // within it, crack the earliest of them and solve the step again on
    // the cracked mesh, until no edge fails (or the limit on crack events
    // is reached). Nothing is committed before: the state is still the
    // step's start.
    const bool splitting = fracture_enabled && parameters.fracture.split_edges;
    // A penalty raised in a solve that a crack makes void is withdrawn.
    const double   start_stiffness = parameters.contact.enabled ?
                                       contacts.get_settings().normal_stiffness :
                                       0.;
    unsigned int   crack_events    = 0;
    Vector<double> d;
    double         dt = 0;
    crack_limit_hit   = false;
    for (;;)
      {
        dt = solve_step(d);
        if (fracture_edges.empty())
          break;
        const auto failing = check_fracture(d, dt);
        if (!splitting || failing.empty())
          break;
        if (crack_events == parameters.fracture.max_crack_events)
          {
            crack_limit_hit = true;
            break;
          }
        if (parameters.contact.enabled)
          contacts.set_normal_stiffness(start_stiffness);
        crack_edges(failing);
        ++crack_events;
      }
    commit_step(d, dt);
    step_controller.accept(dt);
    n_crack_events += crack_events;
    ++step_number;
    record_measure_points();
    last_step_time = wall.wall_time();
    record_statistics(dt);
    // The statistics of this step are recorded before a crawling run is
    // stopped.
    step_controller.check_progress(time);
  }



  template <int dim>
  void
  Simulator<dim>::record_statistics(const double dt)
  {
    step_report.dt                = dt;
    step_report.cuts              = step_controller.n_cuts();
    step_report.open_close_cuts   = step_controller.n_open_close_cuts();
    step_report.solver_iterations = last_solver_iterations;
    step_report.matrix_builds     = n_matrix_rebuilds;
    step_report.max_increment     = max_increment;
    step_report.fracture          = fracture_enabled;
    step_report.crack_events      = n_crack_events;
    step_report.crack_limit_hit   = crack_limit_hit;
    step_report.failing_edges     = n_failing_edges;
    for (const auto &postprocessor : parameters.postprocess.postprocessors)
      postprocessor->add_statistics(*this, statistics);
  }



  template <int dim>
  double
  Simulator<dim>::energy_error() const
  {
    const double spring_energy =
      parameters.contact.enabled ? contacts.get_statistics().spring_energy : 0.;
    return kinetic_energy() + strain_energy() + spring_energy - load_work -
           initial_kinetic_energy;
  }



  template <int dim>
  void
  Simulator<dim>::output_results()
  {
    TimerOutput::Scope scope(timer, "output");
    visualization.write_frame(*this, parameters.postprocess.postprocessors);
  }



  template <int dim>
  void
  Simulator<dim>::write_statistics() const
  {
    std::ofstream out(parameters.output.directory + "statistics");
    statistics.write_text(out,
                          TableHandler::table_with_separate_column_description);

    std::ofstream history(parameters.output.directory + "measure_points.txt");
    history << "# time";
    for (unsigned int m = 0; m < measure_points.size(); ++m)
      {
        const auto &p = parameters.output.measure_points[m];
        history << "  [point " << m << " at " << p[0] << " " << p[1]
                << ": u_x u_y v_x v_y sigma_xx sigma_yy sigma_xy]";
      }
    history << '\n' << std::setprecision(10);
    if (!measure_histories.empty())
      for (unsigned int s = 0; s < measure_histories[0].size(); ++s)
        {
          history << measure_histories[0][s].time;
          for (const auto &h : measure_histories)
            history << ' ' << h[s].displacement << ' ' << h[s].velocity << ' '
                    << h[s].stress[0][0] << ' ' << h[s].stress[1][1] << ' '
                    << h[s].stress[0][1];
          history << '\n';
        }
  }



  template <int dim>
  void
  Simulator<dim>::run()
  {
    if (!is_set_up)
      setup();

    // Everything is checked: only now is anything written.
    const std::string &directory = parameters.output.directory;
    std::filesystem::create_directories(directory);
    log_file.open(directory + "log.txt");
    tee_buffer =
      std::make_unique<TeeBuffer>(std::cout.rdbuf(), log_file.rdbuf());
    console.rdbuf(tee_buffer.get());
    if (parameters_from_file)
      {
        std::ofstream used(directory + "parameters.prm");
        prm.print_parameters(used, ParameterHandler::PRM);
      }

    pcout << "ndda: scene '" << parameters.scene_name << "'\n"
          << "  blocks: " << mesh.n_blocks()
          << ", cells: " << mesh.get_triangulation().n_active_cells()
          << ", vertices: " << mesh.get_triangulation().n_vertices()
          << ", degrees of freedom: " << dof_handler.n_dofs() << " ("
          << fe->base_element(0).get_name() << ")\n"
          << "  constrained nodes: "
          << boundary_constraints.constrained_nodes().size()
          << ", output: " << directory << std::endl;

    Timer        wall;
    double       last_progress      = 0;
    unsigned int last_progress_step = 0;
    const double end_time           = parameters.control.end_time;
    const double interval           = parameters.output.interval;
    output_results();
    next_output_time = interval;
    while (time < end_time * (1. - 1e-12))
      {
        try
          {
            do_time_step();
          }
        catch (...)
          {
            // Keep the rows since the last progress line: they show how
            // the run went wrong.
            write_statistics();
            throw;
          }
        if (time >= next_output_time * (1. - 1e-12) ||
            time >= end_time * (1. - 1e-12))
          {
            output_results();
            if (interval > 0)
              while (next_output_time <= time * (1. + 1e-12))
                next_output_time += interval;
          }
        if (wall.wall_time() - last_progress >=
              parameters.output.progress_interval ||
            time >= end_time * (1. - 1e-12))
          {
            // The wall time goes here, to the log; the statistics file
            // has it only with the 'wall time' postprocessor, so that it
            // is the same in every run.
            const double steps_since = step_number - last_progress_step;
            const double per_step =
              (wall.wall_time() - last_progress) / std::max(steps_since, 1.);
            last_progress      = wall.wall_time();
            last_progress_step = step_number;
            const double rate  = time / std::max(wall.wall_time(), 1e-9);
            pcout << "  step " << std::setw(7) << step_number
                  << "  t = " << std::setw(12) << std::setprecision(6) << time
                  << " s  dt = " << std::setw(10)
                  << step_controller.last_step_size() << " s"
                  << "  cuts " << step_controller.n_total_cuts()
                  << std::setprecision(3) << "  wall " << per_step
                  << " s/step  ETA "
                  << std::max(0., (end_time - time) / std::max(rate, 1e-300))
                  << " s" << std::endl;
            write_statistics();
          }
      }
    write_statistics();
    pcout << "  done: " << step_number << " steps, "
          << step_controller.n_total_cuts() << " step cuts, "
          << n_matrix_rebuilds << " matrix builds, "
          << linear_solver->n_factorizations() << " factorizations, "
          << wall.wall_time() << " s wall time" << std::endl;
    timer.print_summary();
    console.flush();
    console.rdbuf(std::cout.rdbuf());
  }



  template class Simulator<2>;
} // namespace ndda
