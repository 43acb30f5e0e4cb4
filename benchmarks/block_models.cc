// SPDX-License-Identifier: GPL-3.0-or-later
//
// Cost of a time step against the number of blocks, per block kinematics
// model (issue 15): staggered dry-stone walls of 1 m x 0.5 m bricks as in
// prm/brick_wall.prm (half bricks at the ends of every second course, a
// fixed base, gravity, DDA, dt = 2 ms unless the ninth argument says
// otherwise, penalty 10 E, friction 35 degrees, KLU unless the third
// argument names another solver), with
// `Control/Kinematics` = meshed, affine and rigid. Walls of
// about 100, 1000, 10,000 and 100,000 bricks (courses x bricks per course:
// 12 x 8, 25 x 40, 100 x 100, 100 x 1000).
//
// Two starts (fifth argument): `ramped` (the default) raises gravity
// linearly from 0 over eight periods of the wall's fundamental mode
// (4 H / c, H the wall's height, c the bar wave speed of the bricks) and
// times the steps that begin after one and a half ramps, when the wall has
// settled: the cost of a wall standing under its own weight. `sudden`
// switches gravity on at t = 0 and times steps 11 to N + 10: the elastic
// walls then ring in their fundamental mode (doc/performance.md), and the
// figures measure the ringing.
//
// For each run: blocks, DoFs, the mean and median
// wall time per step over the timed steps, that time per brick, open-close
// iterations of the accepted attempt, step cuts (each cut retries the
// step with its own iterations), factorizations per step, the mean
// accepted step over the nominal 2 ms (below 1 where steps were cut: the
// time per step then covers less simulated time), and the set-up time in
// seconds (meshing, element matrices, sparsity), and the run's peak
// resident memory in MB (VmHWM, reset before each run).
//
// The detection distance (sixth argument): `motion` (the default, as in
// ndda) keeps `Control/Maximum displacement ratio` = 0.01 and sets
// `Contact/Detection distance = motion`, a distance that follows the
// wall's motion (doc/contact.md). `scene` sets `Detection distance =
// scene`, Shi's distance, twice the largest step displacement: 2 x 0.01 x
// half the wall's height, 0.06 m for 12 courses, 0.125 m for 25 and 0.5 m
// for 100, and a brick of the tall walls has more candidate contacts
// (bricks two courses away). `brick` is `scene` with the ratio scaled by
// 12 / courses, so that every wall has the 12-course wall's 0.06 m: the
// same work per brick.
//
// The seventh argument `only` runs the largest wall alone; `prm` runs
// nothing and writes the largest wall (with the first of the models) to
// the standard output as a scene for build/ndda, which ends where the timed
// steps would and writes the statistics columns of the postprocessors
// `time step, contact, energy, wall time`: a run end to end, step by step.
// With NDDA_TIMER_TABLE=1 each run's timer table (set-up and every step)
// goes to the error stream.
//
// The eighth argument chooses where a sliding contact's friction takes its
// normal force from: `same` (the default) the same solve, which makes the
// matrix non-symmetric; `lagged` the solve before (Contact/penalty
// Coulomb/Lagged friction, as Shi's DDA), which keeps it symmetric;
// `lagged:x` the same with Lagged friction tolerance = x.
//
// The ninth argument is the time step (s; default 2e-3). The ramp and the
// untimed start are simulated times and do not change with it.
//
// Usage: block_models [steps] [largest wall: 1, 2, 3 or 4] [linear solver]
//                     [models, comma-separated] [ramped | sudden]
//                     [scene | brick | motion] [all | only | prm]
//                     [same | lagged | lagged:tolerance] [time step]
//        (default 50, 2, KLU, meshed,affine,rigid, ramped, motion, all,
//        same, 2e-3)

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <ndda/parameters/parameters.h>
#include <ndda/simulator.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "plain_system.h"

namespace
{
  /** The walls, courses x bricks per course. */
  constexpr unsigned int wall_sizes[4][2] = {{12, 8},
                                             {25, 40},
                                             {100, 100},
                                             {100, 1000}};

  /** Young's modulus and density of the bricks. */
  constexpr double youngs_modulus = 10e9, density = 2600;

  /** The time over which a ramped start raises gravity: eight periods
   * of the fundamental (axial) mode of a wall of @p courses courses. */
  double
  ramp_time(const unsigned int courses)
  {
    const double height = 0.5 * courses;
    return 8 * 4 * height / std::sqrt(youngs_modulus / density);
  }

  /** The wall scene of @p courses courses of @p length bricks; gravity
   * reaches its full value at @p ramp (at once if it is 0). */
  std::string
  wall(const unsigned int courses,
       const unsigned int length,
       const std::string &model,
       const std::string &solver,
       const double       ramp,
       const double       displacement_ratio,
       const std::string &detection,
       const std::string &lag_tolerance,
       const double       time_step,
       const double       end_time,
       const std::string &postprocessors)
  {
    const double       w = length, h = 0.5 * courses;
    std::ostringstream joints;
    joints << std::setprecision(10);
    std::string separator;
    for (unsigned int c = 1; c < courses; ++c)
      {
        joints << separator << 0 << ", " << 0.5 * c << ", " << w << ", "
               << 0.5 * c;
        separator = "; ";
      }
    for (unsigned int c = 0; c < courses; ++c)
      for (unsigned int i = 1; i <= length; ++i)
        {
          const double x = i - (c % 2 == 1 ? 0.5 : 0.);
          if (x <= 0 || x >= w)
            continue;
          joints << separator << x << ", " << 0.5 * c << ", " << x << ", "
                 << 0.5 * (c + 1);
        }
    std::ostringstream text;
    text << std::setprecision(10) << R"(
set Scene name = wall
subsection Control
  set Analysis type   = dynamic
  set Time integrator = DDA
  set Time step       = )"
         << time_step << R"(
  set End time        = )"
         << end_time << R"(
  set Maximum displacement ratio = )"
         << displacement_ratio << R"(
  set Linear solver = )"
         << solver << R"(
  set Kinematics = )"
         << model << R"(
end
subsection Contact
  set Penalty factor = 10
  set Detection distance = )"
         << detection << R"(
  subsection penalty Coulomb
    set Lagged friction = )"
         << (lag_tolerance.empty() ? "false" : "true") << R"(
    set Lagged friction tolerance = )"
         << (lag_tolerance.empty() ? "1e-3" : lag_tolerance) << R"(
  end
end
subsection Materials
  set Names = rock
  subsection rock
    set Density         = )"
         << density << R"(
    set Young's modulus = )"
         << youngs_modulus << R"(
    set Poisson's ratio = 0.25
  end
  subsection Joint
    set Friction angle = 35
  end
end
subsection Geometry
  set Blocks  = base
  set Regions = wall
  subsection base
    set Outer boundary = -1, -1; )"
         << w + 1 << ", -1; " << w + 1 << ", 0; -1, 0"
         << R"(
    set Material = rock
    set Mesh size = 2
  end
  subsection wall
    set Outer boundary = 0, 0; )"
         << w << ", 0; " << w << ", " << h << "; 0, " << h << R"(
    set Joints = )"
         << joints.str() << R"(
    set Material = rock
    set Mesh size = 2
  end
end
subsection Loads
  set Gravity = 0; -9.81)"
         << (ramp > 0 ? "*min(1, t/" + std::to_string(ramp) + ")" : "") << R"(
end
subsection Boundary conditions
  set Names = ground
  subsection ground
    set Type     = fixed
    set Segments = -1, -1, )"
         << w + 1 << R"(, -1
  end
end
subsection Output
  set Write vtu = false
end
)";
    if (!postprocessors.empty())
      text << "subsection Postprocess\n  set List of postprocessors = "
           << postprocessors << "\nend\n";
    return text.str();
  }

  void
  run(const unsigned int courses,
      const unsigned int length,
      const std::string &model,
      const std::string &solver,
      const unsigned int steps,
      const bool         ramped,
      const std::string &detection,
      const std::string &lag_tolerance,
      const double       time_step,
      const bool         write_scene)
  {
    const double ramp = ramped ? ramp_time(courses) : 0.;
    // Shi's detection distance is 2 x the ratio x half the scene's height:
    // 0.06 m for 12 courses, 0.5 m for 100. `brick` keeps it at 0.06 m.
    const double ratio = detection == "brick" ? 0.01 * 12. / courses : 0.01;
    // The untimed start: ten steps, or one and a half ramps.
    const unsigned int skip = 10;
    const double       end_time =
      std::max(skip * time_step, 1.5 * ramp) + steps * time_step;
    const auto scene = [&](const double end_time, const std::string &output) {
      return wall(courses,
                  length,
                  model,
                  solver,
                  ramp,
                  ratio,
                  detection == "motion" ? "motion" : "scene",
                  lag_tolerance,
                  time_step,
                  end_time,
                  output);
    };
    if (write_scene)
      {
        // The same run as a scene for build/ndda: it ends where the timed
        // steps would.
        std::cout << scene(end_time, "time step, contact, energy, wall time");
        return;
      }
    plain_system::reset_peak_rss();
    dealii::ParameterHandler     prm;
    ndda::parameters::Parameters parameters;
    // The run below stops itself; the scene ends two steps later.
    parameters.read(scene(end_time + 2 * time_step, ""), "wall.prm", prm);
    ndda::Simulator<2> simulator(parameters);
    const auto         start_setup = std::chrono::steady_clock::now();
    simulator.setup();
    const double setup = std::chrono::duration<double>(
                           std::chrono::steady_clock::now() - start_setup)
                           .count();
    // A line on the error stream at most every 30 s: the large walls take
    // seconds a step.
    auto       last_report = std::chrono::steady_clock::now();
    const auto progress    = [&](const unsigned int step, const double time) {
      const auto now = std::chrono::steady_clock::now();
      if (std::chrono::duration<double>(now - last_report).count() < 30)
        return;
      last_report = now;
      std::cerr << "  " << model << " " << courses << " x " << length
                << ": step " << step << ", t = " << time << " s, resident "
                << plain_system::status_bytes("VmRSS") / 1e6 << " MB"
                << std::endl;
    };
    double       time = 0;
    unsigned int step = 0;
    for (; step < skip || time < 1.5 * ramp; ++step)
      {
        simulator.do_time_step();
        time += simulator.get_step_report().dt;
        progress(step + 1, time);
      }
    std::vector<double> times;
    unsigned int        iterations = 0, cuts = 0;
    const unsigned int  factorizations = simulator.n_factorizations();
    double              simulated      = 0;
    for (unsigned int s = 0; s < steps; ++s)
      {
        const auto start = std::chrono::steady_clock::now();
        simulator.do_time_step();
        times.push_back(std::chrono::duration<double>(
                          std::chrono::steady_clock::now() - start)
                          .count());
        iterations += simulator.get_contacts().get_statistics().n_iterations;
        cuts += simulator.get_step_report().cuts;
        simulated += simulator.get_step_report().dt;
        progress(step + s + 1, time + simulated);
      }
    if (std::getenv("NDDA_TIMER_TABLE") != nullptr)
      simulator.get_timer().print_summary(std::cerr);
    // Where the wall ends: at rest if it stands (a ramped start), its
    // kinetic energy against the work of its weight over its largest
    // settlement.
    {
      const double settlement = simulator.get_displacement().linfty_norm();
      const double weight     = density * 9.81 * 0.5 * courses * length;
      std::cerr << "  " << model << " " << courses << " x " << length
                << " at the end: t = " << simulator.get_time() << " s, step "
                << simulator.get_step_number() << ", largest displacement "
                << settlement << " m, largest speed "
                << simulator.get_velocity().linfty_norm()
                << " m/s, kinetic energy " << simulator.kinetic_energy()
                << " J = " << simulator.kinetic_energy() / (weight * settlement)
                << " of weight x largest displacement, energy error "
                << simulator.energy_error() << " J" << std::endl;
    }
    double total = 0;
    for (const double t : times)
      total += t;
    std::vector<double> sorted(times);
    std::sort(sorted.begin(), sorted.end());
    const unsigned int bricks = simulator.get_mesh().n_blocks() - 1;
    const double       mean   = 1e3 * total / times.size();
    std::cout << std::setw(8) << model << std::setw(8) << bricks << std::setw(9)
              << simulator.get_dof_handler().n_dofs() << std::fixed
              << std::setprecision(3) << std::setw(11) << mean << std::setw(11)
              << 1e3 * sorted[sorted.size() / 2] << std::setw(12)
              << 1e3 * mean / bricks << std::setprecision(2) << std::setw(8)
              << double(iterations) / times.size() << std::setw(8)
              << double(cuts) / times.size() << std::setw(8)
              << double(simulator.n_factorizations() - factorizations) /
                   times.size()
              << std::setw(8) << simulated / (time_step * times.size())
              << std::setprecision(1) << std::setw(9) << setup
              << std::setprecision(0) << std::setw(9)
              << plain_system::status_bytes("VmHWM") / 1e6 << std::defaultfloat
              << std::endl;
    std::cout << "@value block_models." << model << "." << bricks << ".ms "
              << std::setprecision(3) << mean << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const unsigned int steps       = argc > 1 ? std::atoi(argv[1]) : 50;
  const unsigned int largest     = argc > 2 ? std::atoi(argv[2]) : 2;
  const std::string  solver      = argc > 3 ? argv[3] : "KLU";
  const std::string  models      = argc > 4 ? argv[4] : "meshed,affine,rigid";
  const std::string  start       = argc > 5 ? argv[5] : "ramped";
  const std::string  detection   = argc > 6 ? argv[6] : "motion";
  const std::string  which       = argc > 7 ? argv[7] : "all";
  const std::string  friction    = argc > 8 ? argv[8] : "same";
  const double       time_step   = argc > 9 ? std::atof(argv[9]) : 2e-3;
  const bool         write_scene = which == "prm";
  const bool         only        = which == "only" || write_scene;
  std::string        lag_tolerance;
  if (friction == "lagged")
    lag_tolerance = "1e-3";
  else if (friction.rfind("lagged:", 0) == 0)
    lag_tolerance = friction.substr(7);
  else if (friction != "same")
    {
      std::cerr << "block_models: the eighth argument must be 'same', "
                   "'lagged' or 'lagged:tolerance', not '"
                << friction << "'" << std::endl;
      return 1;
    }
  if (detection != "scene" && detection != "brick" && detection != "motion")
    {
      std::cerr << "block_models: the sixth argument must be 'scene', "
                   "'brick' or 'motion', not '"
                << detection << "'" << std::endl;
      return 1;
    }
  if (start != "ramped" && start != "sudden")
    {
      std::cerr << "block_models: the fifth argument must be 'ramped' or "
                   "'sudden', not '"
                << start << "'" << std::endl;
      return 1;
    }
  if (which != "all" && which != "only" && which != "prm")
    {
      std::cerr << "block_models: the seventh argument must be 'all', "
                   "'only' or 'prm', not '"
                << which << "'" << std::endl;
      return 1;
    }
  if (!(time_step > 0.))
    {
      std::cerr << "block_models: the ninth argument, the time step, must be "
                   "a positive number (s), not '"
                << argv[9] << "'" << std::endl;
      return 1;
    }
  const bool ramped   = start == "ramped";
  const auto run_wall = [&](const unsigned int size, const std::string &model) {
    run(wall_sizes[size][0],
        wall_sizes[size][1],
        model,
        solver,
        steps,
        ramped,
        detection,
        lag_tolerance,
        time_step,
        write_scene);
  };
  if (write_scene)
    {
      // The scene of the largest wall with the first of the models.
      run_wall(std::min(std::max(largest, 1u), 4u) - 1,
               models.substr(0, models.find(',')));
      return 0;
    }
  if (ramped)
    std::cout << steps
              << " steps of each run after gravity was ramped over 8 "
                 "periods of the wall's fundamental mode and held half as "
                 "long, "
              << solver << ", detection distance: " << detection << std::endl;
  else
    std::cout << "steps 11 to " << steps + 10
              << " of each run, gravity switched on at t = 0, " << solver
              << ", detection distance: " << detection << std::endl;
  std::cout << std::setw(8) << "model" << std::setw(8) << "bricks"
            << std::setw(9) << "DoFs" << std::setw(11) << "ms/step"
            << std::setw(11) << "median" << std::setw(12) << "us/brick"
            << std::setw(8) << "o-c it" << std::setw(8) << "cuts"
            << std::setw(8) << "fact." << std::setw(8) << "dt/dt0"
            << std::setw(9) << "setup s" << std::setw(9) << "peak MB"
            << std::endl;
  for (unsigned int s = only ? std::min(largest, 4u) - 1 : 0;
       s < largest && s < 4;
       ++s)
    for (const std::string model : {"meshed", "affine", "rigid"})
      if (("," + models + ",").find("," + model + ",") != std::string::npos)
        run_wall(s, model);
}
