// SPDX-License-Identifier: GPL-3.0-or-later

#include <deal.II/dofs/dof_tools.h>

#include <ndda/base/stage_reporter.h>
#include <ndda/base/threads.h>
#include <ndda/physics/free_bodies.h>
#include <ndda/scene/scene.h>
#include <ndda/simulator.h>

#include <algorithm>
#include <filesystem>
#include <sstream>

namespace ndda
{
  namespace
  {
    /// A block that turns by less than this in a step (rad) is solved
    /// without the rotation correction (add_rotation_correction()): it
    /// would move the block's forces by less than this fraction of its
    /// elastic forces, and the flutter it prevents (a factor of about 1.4
    /// in energy per radian turned, measured at its worst) would take a
    /// million such steps a radian. Blocks that rock in contact stay
    /// below it and save the second solve.
    constexpr double min_corrected_rotation = 1e-6;
  } // namespace



  template <int dim>
  Simulator<dim>::Simulator(const std::string &parameter_file,
                            const MPI_Comm     communicator)
    : Simulator(parameters::Parameters(), nullptr, communicator)
  {
    parameters.read_file(parameter_file, prm);
    parameters_from_file = true;
    // Kept for checkpoints: a resumed run reads the scene as it was.
    std::ifstream      in(parameter_file);
    std::ostringstream text;
    text << in.rdbuf();
    parameter_text      = text.str();
    parameter_file_name = std::filesystem::absolute(parameter_file).string();
  }



  template <int dim>
  Simulator<dim>::Simulator(const parameters::Parameters &parameters,
                            const Triangulation<dim>     *triangulation,
                            const MPI_Comm                communicator)
    : communicator(Utilities::MPI::job_supports_mpi() ? communicator :
                                                        MPI_COMM_SELF)
    , n_processes(Utilities::MPI::job_supports_mpi() ?
                    Utilities::MPI::n_mpi_processes(communicator) :
                    1)
    , this_process(Utilities::MPI::job_supports_mpi() ?
                     Utilities::MPI::this_mpi_process(communicator) :
                     0)
    , parameters(parameters)
    // Only the first process speaks; the others' console goes nowhere.
    , console(this_process == 0 ? std::cout.rdbuf() : nullptr)
    , pcout(console, this_process == 0)
    , timer()
    , mesh(this->communicator)
    , fem(mesh, timer)
  {
    set_up_threads();
    fem.communicator = this->communicator;
    if (triangulation != nullptr)
      {
        user_triangulation = std::make_unique<Triangulation<dim>>();
        user_triangulation->copy_triangulation(*triangulation);
      }
  }



  template <int dim>
  Simulator<dim>::~Simulator()
  {
    log_file.close();
  }



  template <int dim>
  void
  Simulator<dim>::setup()
  {
    SectionTimer::Scope scope(timer, "setup");
    // A large scene says what it is doing once a stage takes more than a
    // few seconds.
    StageReporter stages(console);
    if (resume_state)
      {
        // The mesh as the run left it, at its initial geometry: everything
        // found by position is found there, as in the run.
        stages.begin("reading the checkpoint");
        read_checkpoint_mesh();
      }
    else
      {
        stages.begin("checking and meshing the geometry");
        scene::build_mesh(parameters, user_triangulation.get(), mesh);
        scene_half_height = scene::half_height(mesh);
      }
    stages.begin("numbering the unknowns");
    fem.setup_kinematics(parameters);
    if (resume_state)
      read_checkpoint_models();

    setup_dofs();
    stages.begin("constraints and the linear system");
    fem.setup_constraints(parameters);
    fem.setup_system(parameters);
    stages.begin("contacts");
    setup_contacts();
    if (parameters.contact.enabled)
      detection.initialize(parameters.contact.detection_rule,
                           contact_distances.detection);
    if (parameters.control.analysis_type == time::AnalysisType::quasi_static &&
        !resume_state)
      require_held_bodies(
        mesh.get_block_mesh(),
        fem.dof_map,
        rigid_supports(mesh.get_block_mesh(),
                       fem.dof_map,
                       fem.constraints,
                       fem.bolts,
                       parameters.contact.enabled ?
                         contacts.get_settings().state_tolerance :
                         -1.),
        "Control/Analysis type = quasi-static");
    stages.begin("fracture, loads and measure points");
    fracture_check.setup(mesh,
                         fem.cell_material,
                         ndda::parameters::material_strengths(
                           parameters.materials),
                         fem.meshed_cells(),
                         parameters.fracture.nonlocal_radius);
    fem.setup_loads(parameters);
    fem.check_expressions(parameters);
    measure_points.setup(
      mesh, *fem.fe, fem.dof_map, parameters.output.measure_points, false);

    stages.begin("stresses and the initial state");
    stresses.initialize(fem.element_cache,
                        fem.dof_map,
                        parameters.materials,
                        fem.cell_material,
                        mesh.get_triangulation(),
                        &fem.owned_cells);
    stresses.reinit(mesh.get_triangulation().n_active_cells(),
                    fem.element_cache.n_quadrature_points());
    scene::set_initial_state(parameters,
                             mesh,
                             fem.dof_handler,
                             fem.mapping,
                             stresses,
                             kinematics.velocity);
    compute_internal_force();
    setup_automatic_kinematics();
    if (!resume_state)
      promote_blocks(nullptr);

    step_controller = time::StepController(scene::step_limits(parameters));
    open_close =
      contact::OpenCloseSolver(scene::open_close_settings(parameters));
    if (resume_state)
      read_checkpoint_state();
    is_set_up = true;
  }



  template <int dim>
  void
  Simulator<dim>::setup_dofs(const bool element_matrices)
  {
    fem.setup_dofs(parameters, element_matrices);
    const unsigned int n = fem.dof_handler.n_dofs();
    displacement.reinit(n);
    kinematics.velocity.reinit(n);
    kinematics.inertia_force.reinit(n);
    if (parameters.control.time_integrator->keeps_acceleration())
      kinematics.acceleration.reinit(n);
    internal_force.reinit(n);
  }



  template <int dim>
  void
  Simulator<dim>::setup_contacts()
  {
    if (parameters.contact.enabled)
      {
        contact_distances = scene::setup_contacts(parameters,
                                                  mesh,
                                                  fem.cell_material,
                                                  fem.dof_map,
                                                  scene_half_height,
                                                  contacts);
        contacts.set_owned_cells(&fem.owned_cells);
        contacts.set_frames(&fem.frames);
        contacts.set_reduced_blocks(fem.reduced_mesh_blocks());
      }
  }



  template <int dim>
  void
  Simulator<dim>::compute_internal_force()
  {
    // f_int = sum over cells of t * int B^T sigma.
    finish_internal_force(stresses.internal_force(internal_force));
  }



  template <int dim>
  void
  Simulator<dim>::finish_internal_force(const double energy)
  {
    // The strain energy is the energy the stresses hold less its initial
    // value.
    if (!initial_strain_energy_known)
      {
        initial_strain_energy       = energy;
        initial_strain_energy_known = true;
      }
    stored_strain_energy = energy - initial_strain_energy;
    // Bolts pull their anchors towards each other with their spring force.
    fem.bolts.add_internal_force(displacement, internal_force);
  }



  template <int dim>
  void
  Simulator<dim>::assemble_external_force(const double    t,
                                          Vector<double> &force) const
  {
    fem.external_force(t, displacement, force);
  }



  template <int dim>
  void
  Simulator<dim>::build_element_matrices(const bool only_moved_cells,
                                         const bool always)
  {
    SectionTimer::Scope scope(timer, "element matrices");
    // The first step uses the element matrices that setup() computed (it
    // needed them for the initial internal force; a tangent that depends
    // on the stress is rebuilt from the initial stresses); later steps
    // recompute those of the cells that moved.
    if (!fem.update_matrices(
          parameters, only_moved_cells, displacement, stresses, always))
      return;
    ++n_matrix_rebuilds;
    compute_internal_force();
  }



  template <int dim>
  time::AttemptResult
  Simulator<dim>::try_time_step(const double dt, Vector<double> &d)
  {
    const auto &integrator = *parameters.control.time_integrator;
    fem.linear_system.prepare_step(dt,
                                   integrator.step_mass_coefficient(dt,
                                                                    kinematics),
                                   integrator.damping_coefficient(dt),
                                   fem.constraints,
                                   fem.penalty_stiffness);

    // Right-hand side at the end of the step (thesis 3.15):
    // f_ext(t1) - f_int + inertia terms of the integrator.
    Vector<double> &rhs = step_rhs;
    {
      SectionTimer::Scope scope(timer, "solve");
      assemble_external_force(time + dt, step_external_force);
      rhs = step_external_force;
      rhs -= internal_force;
      integrator.add_inertia_terms(fem.linear_system.get_mass_matrix(),
                                   kinematics,
                                   dt,
                                   rhs);
    }
    Vector<double> &prescribed = step_prescribed;
    prescribed.reinit(fem.dof_handler.n_dofs());
    fem.constraints.prescribed_increment(time, dt, displacement, prescribed);
    if (!fem.constraints.exact())
      fem.constraints.add_penalty_forces(fem.penalty_stiffness,
                                         prescribed,
                                         rhs);

    if (!std::isfinite(rhs.l1_norm()))
      {
        require_finite(step_external_force,
                       dt,
                       "the external force",
                       "A load's value is not finite.");
        require_finite(internal_force,
                       dt,
                       "the internal force",
                       "A stress is not finite.");
        require_finite(rhs,
                       dt,
                       "the inertia force",
                       "A velocity or acceleration is not finite.");
      }
    const auto solve = [&]() {
      const bool settled =
        open_close.solve(fem.linear_system,
                         parameters.contact.enabled ? &contacts : nullptr,
                         rhs,
                         prescribed,
                         fem.constraints,
                         d,
                         inertia_correction);
      require_finite(
        d,
        dt,
        "the displacement increment solved for",
        "The right-hand side was finite, so the system is singular: in a "
        "static or quasi-static scene a block with no constraint and no "
        "closed contact, or a block held by a single point, can move "
        "freely; or the step's matrix holds a value that is not finite.");
      return settled;
    };
    if (!solve())
      return time::AttemptResult::not_settled;

    // The element matrices count the rotation of a strained block as
    // strain, which the step's end does not have: take that force out
    // and solve once more (doc/theory.md, "Spin and strain").
    // The blocks' rotations in d are kept for commit_step().
    const std::vector<bool> &straining = fem.straining_blocks();
    solved_rotation.clear();
    if (std::find(straining.begin(), straining.end(), true) != straining.end())
      {
        solved_rotation =
          block_rotations(mesh, fem.dof_map, stresses, fem.block_nodes, d);
        std::vector<double> correction(solved_rotation);
        bool                turned = false;
        for (unsigned int b = 0; b < correction.size(); ++b)
          if (!straining[b] ||
              std::abs(correction[b]) <= min_corrected_rotation)
            correction[b] = 0.;
          else
            turned = true;
        if (turned)
          {
            add_rotation_correction(mesh,
                                    fem.dof_map,
                                    fem.element_cache,
                                    fem.frames,
                                    correction,
                                    d,
                                    rhs);
            if (!solve())
              return time::AttemptResult::not_settled;
            solved_rotation =
              block_rotations(mesh, fem.dof_map, stresses, fem.block_nodes, d);
          }
      }
    return check_increment(d);
  }



  template <int dim>
  time::AttemptResult
  Simulator<dim>::check_increment(const Vector<double> &d)
  {
    // DDA step control: the largest nodal displacement must stay below the
    // allowed fraction of half the scene height.
    max_increment = fem.dof_map.max_vertex_norm(d);
    if (max_increment >
        parameters.control.max_displacement_ratio * scene_half_height)
      return time::AttemptResult::too_large;
    // Contacts detected within a distance that follows the motion: an
    // attempt that moved further may have missed one. Detect again within
    // the widened distance; only if it finds more candidates, solve again.
    if (parameters.contact.enabled && !detection.covers(max_increment))
      {
        SectionTimer::Scope scope(timer, "contact detection");
        if (contacts.finds_more(mesh.get_block_mesh().vertices,
                                detection.widen(max_increment),
                                detection.skin()))
          return time::AttemptResult::detect_again;
      }
    // A cell that the increment turns inside out: no strain measure of the
    // linear update holds there (its strain energy changes sign). Only a
    // diverging motion or a step far too large does this; cut the step.
    if (mesh.inverts_a_cell(fem.dof_map.vertex_values(d)))
      return time::AttemptResult::inverted;
    if (parameters.contact.enabled &&
        parameters.contact.penalty_method ==
          parameters::PenaltyMethod::automatic &&
        contacts.max_penetration(d) > contact_distances.penetration_tolerance)
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
    SectionTimer::Scope scope(timer, "update");
    // Velocity and acceleration at the end of the step.
    const auto &mass = fem.linear_system.get_mass_matrix();
    parameters.control.time_integrator->update(
      d, dt, mass, inertia_correction, kinematics);

    // Each block's rotation made exact: its linearised rotation in d is
    // replaced by the finite one, and its velocity and acceleration turn
    // with it.
    Vector<double> &motion = step_motion;
    motion                 = d;
    const std::vector<double> rotation =
      rotate_blocks(mesh,
                    fem.dof_map,
                    stresses,
                    fem.block_nodes,
                    solved_rotation,
                    dt,
                    motion,
                    kinematics.velocity,
                    kinematics.inertia_force,
                    kinematics.acceleration.size() > 0 ?
                      &kinematics.acceleration :
                      nullptr);
    // The blocks' frames turn with them: their matrices stay.
    fem.frames.turn(rotation);
    // A rigid block in the global frame that turned needs new lines.
    block_lines_stale = fem.reduced_blocks.stale(rotation);
    if (parameters.contact.enabled)
      contacts.end_step(motion);

    // Objective update on the step's start geometry: each point's stress
    // turns by the increment's rotation there, exactly, and takes the
    // stress of its stretch; in the same pass over the cells, the
    // internal force of the new stresses on the step's end geometry, and
    // the strain energy they hold.
    const double energy =
      stresses.advance_with_internal_force(motion, internal_force);

    fem.bolts.update(displacement, motion);

    // Work of the loads over the step, by the trapezoidal rule; of the
    // prescribed motion, as the last solve's reactions did it; and the
    // viscous dissipation.
    load_work += 0.5 * (external_force * motion + step_external_force * motion);
    prescribed_work += fem.linear_system.last_constraint_work();
    if (fem.linear_system.has_damping())
      add_viscous_work(d, dt);
    external_force = step_external_force;

    displacement += motion;
    mesh.move_vertices(fem.dof_map.vertex_values(motion));
    time += dt;

    finish_internal_force(energy);
  }



  template <int dim>
  void
  Simulator<dim>::prepare_step()
  {
    if (step_number > 0)
      {
        if (block_lines_stale)
          {
            fem.setup_system(parameters);
            block_lines_stale = false;
            build_element_matrices(true, true);
          }
        else
          build_element_matrices(true);
        return;
      }
    build_element_matrices(false);
    // A reduced block moves in its space from the start: its initial
    // velocity is fitted, keeping momentum and angular momentum.
    fem.reduced_blocks.project(fem.linear_system.get_mass_matrix(),
                               kinematics.velocity);
    const auto &integrator = *parameters.control.time_integrator;
    if (integrator.needs_initial_acceleration())
      kinematics.inertia_force =
        fem.initial_inertia_force(time, displacement, internal_force);
    // A scheme that keeps the acceleration finds its own with the first
    // step (KinematicState::starting).
    kinematics.starting = integrator.keeps_acceleration();
    if (measure_points.waiting_for_first_sample())
      measure_points.record(time, displacement, kinematics.velocity, stresses);
    assemble_external_force(time, external_force);
    initial_kinetic_energy = kinetic_energy();
  }



  template <int dim>
  double
  Simulator<dim>::solve_step(Vector<double> &d)
  {
    // Contacts are detected once per step, on the geometry of its start,
    // within a distance that covers the step's motion (DetectionDistance):
    // Shi's distance covers every step size the cuts may try; one that
    // follows the motion is widened, and the step detected again, when an
    // attempt moves further.
    double dt = step_controller.attempt_size(time);
    if (parameters.contact.enabled)
      detect_contacts(detection.for_step(dt));
    time::AttemptResult result;
    while ((result = try_time_step(dt, d)) != time::AttemptResult::accepted)
      {
        if (result == time::AttemptResult::detect_again)
          {
            detect_contacts(detection.get());
            continue;
          }
        if (parameters.contact.enabled)
          contacts.restart_step();
        dt = step_controller.after_failure(result, dt, max_increment);
      }
    if (parameters.contact.enabled)
      detection.accept(dt,
                       max_increment,
                       detection.follows_motion() ? contacts.max_depth(d) : 0.);
    return dt;
  }



  template <int dim>
  void
  Simulator<dim>::detect_contacts(const double distance)
  {
    {
      SectionTimer::Scope scope(timer, "contact detection");
      contacts.begin_step(mesh.get_block_mesh().vertices,
                          distance,
                          detection.skin());
    }
    if (fem.linear_system.update_contact_couplings(contacts.get_couplings(),
                                                   fem.dof_map,
                                                   fem.constraints))
      fem.assemble(displacement);
  }



  template <int dim>
  void
  Simulator<dim>::do_time_step()
  {
    if (!is_set_up)
      setup();
    WallClock wall;
    prepare_step();
    step_controller.begin_step(step_number + 1, time);

    // The crack sequence (thesis 5.4): solve the step; if edges fail
    // within it, crack the earliest of them and solve the step again on
    // the cracked mesh, until no edge fails (or the limit on crack events
    // is reached). Nothing is committed before: the state is still the
    // step's start.
    const bool splitting =
      fracture_check.enabled() && parameters.fracture.split_edges;
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
        // Kinematics = auto: a block that the step brings near failure is
        // meshed, and the step solved again.
        if (promote_blocks(&d))
          {
            if (parameters.contact.enabled)
              contacts.set_normal_stiffness(start_stiffness);
            continue;
          }
        if (fracture_check.get_edges().empty())
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
        crack_edges(parameters.fracture.align_crack_paths ?
                      advance_crack_tips(failing, d) :
                      failing);
        ++crack_events;
      }
    commit_step(d, dt);
    demote_blocks();
    step_controller.accept(dt);
    n_crack_events += crack_events;
    ++step_number;
    measure_points.record(time, displacement, kinematics.velocity, stresses);
    last_step_time = wall.seconds();
    record_statistics(dt);
    // The statistics of this step are recorded before a crawling run is
    // stopped.
    step_controller.check_progress(time);
  }



  template class Simulator<2>;
} // namespace ndda
