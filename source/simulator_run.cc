// SPDX-License-Identifier: GPL-3.0-or-later
//
// The Simulator's time loop and what it writes: statistics, frames,
// checkpoints.

#include <ndda/base/atomic_file.h>
#include <ndda/base/stage_reporter.h>
#include <ndda/simulator.h>

#include <cstdio>
#include <filesystem>

namespace ndda
{
  template <int dim>
  void
  Simulator<dim>::record_statistics(const double dt)
  {
    step_report.dt                = dt;
    step_report.cuts              = step_controller.n_cuts();
    step_report.open_close_cuts   = step_controller.n_open_close_cuts();
    step_report.solver_iterations = open_close.last_solver_iterations();
    step_report.matrix_builds     = n_matrix_rebuilds;
    step_report.max_increment     = max_increment;
    step_report.fracture          = fracture_check.enabled();
    step_report.crack_events      = n_crack_events;
    step_report.crack_limit_hit   = crack_limit_hit;
    step_report.failing_edges     = fracture_check.n_failing_edges();
    statistics.start_row();
    for (const auto &postprocessor : parameters.postprocess.postprocessors)
      postprocessor->add_statistics(*this, statistics);
  }



  template <int dim>
  void
  Simulator<dim>::output_results()
  {
    SectionTimer::Scope scope(timer, "output");
    visualization.write_frame(*this, parameters.postprocess.postprocessors);
  }



  template <int dim>
  void
  Simulator<dim>::write_statistics()
  {
    if (!writes_files())
      return;
    statistics.write(parameters.output.directory + "statistics");
    measure_points.write(parameters.output.directory + "measure_points.txt");
  }



  template <int dim>
  void
  Simulator<dim>::run()
  {
    if (!is_set_up)
      setup();
    const bool resumed = resume_state != nullptr;

    // Everything is checked: only now is anything written.
    const std::string &directory = parameters.output.directory;
    std::filesystem::create_directories(directory);
    if (writes_files())
      {
        log_file.open(directory + "log.txt", console, resumed);
        if (resumed)
          continue_files();
        else if (parameters_from_file)
          {
            AtomicFile used(directory + "parameters.prm");
            prm.print_parameters(used.stream(), ParameterHandler::PRM);
            used.commit();
          }
      }

    pcout << "ndda: scene '" << parameters.scene_name << "'\n"
          << fem.summary() << ", output: " << directory << std::endl;
    if (n_processes > 1)
      {
        const auto solver = parameters.control.linear_solver;
        const bool shared = solver == parameters::LinearSolverType::mumps ||
                            solver == parameters::LinearSolverType::cg_amg;
        pcout << "  on " << n_processes << " MPI processes, "
              << (shared ? "which solve the linear systems together" :
                           "the first one solving the linear systems for all "
                           "(the run on one process to the bit; Linear "
                           "solver = MUMPS or CG-AMG shares the solve)")
              << std::endl;
      }
    if (resumed)
      pcout << "  resumed from " << directory << "checkpoint.ndda at step "
            << step_number << ", t = " << time << " s" << std::endl;

    WallClock                   wall;
    postprocess::ProgressReport progress(parameters.output.progress_interval);
    postprocess::OutputSchedule schedule(parameters.output.interval,
                                         parameters.control.end_time);
    const double checkpoint_interval = parameters.output.checkpoint_interval;
    postprocess::OutputSchedule checkpoints(checkpoint_interval,
                                            parameters.control.end_time);
    AssertThrow(checkpoint_interval == 0. || !parameter_text.empty(),
                ExcMessage("Output/Checkpoint interval: checkpoints hold the "
                           "scene's .prm file, and this scene was not read "
                           "from one. Set the interval to 0."));
    if (resumed)
      {
        // The frame and the checkpoint of the present time were written
        // before the run stopped.
        schedule.frame_due(time);
        checkpoints.frame_due(time);
        resume_state.reset();
      }
    else
      output_results();
    // A step that takes long (many cuts, a cascade of cracks) says so.
    StageReporter long_step(console, 10., 30., "");
    while (!schedule.finished(time))
      {
        try
          {
            char t[32];
            std::snprintf(t, sizeof(t), "%.6g", time);
            long_step.begin("step " + std::to_string(step_number + 1) +
                            " at t = " + t + " s");
            do_time_step();
          }
        catch (...)
          {
            // Keep the rows since the last progress line: they show how
            // the run went wrong.
            write_statistics();
            throw;
          }
        if (schedule.frame_due(time))
          output_results();
        if (checkpoint_interval > 0. && checkpoints.frame_due(time))
          {
            long_step.begin(
              "writing a checkpoint at t = " + std::to_string(time) + " s");
            write_checkpoint();
          }
        if (progress.due(wall.seconds(), schedule.finished(time)))
          {
            progress.print(console,
                           wall.seconds(),
                           {step_number,
                            time,
                            parameters.control.end_time,
                            step_controller.last_step_size(),
                            step_controller.n_total_cuts()});
            write_statistics();
          }
      }
    long_step.end();
    write_statistics();
    pcout << "  done: " << step_number << " steps, "
          << step_controller.n_total_cuts() << " step cuts, "
          << n_matrix_rebuilds << " matrix builds, "
          << fem.linear_system.n_factorizations() << " factorizations, "
          << wall.seconds() << " s wall time" << std::endl;
    if (pcout.is_active())
      timer.print_summary(pcout.get_stream());
    log_file.close();
  }



  template void
  Simulator<2>::record_statistics(const double);
  template void
  Simulator<2>::output_results();
  template void
  Simulator<2>::write_statistics();
  template void
  Simulator<2>::run();
} // namespace ndda
