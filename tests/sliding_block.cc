// SPDX-License-Identifier: GPL-3.0-or-later
//
// A block on a 30 degree incline under gravity (contact issue, first
// "must show" item). The incline is a fixed elastic block whose top face
// rises at 30 degrees; the 1 m x 0.5 m block lies on it, at rest, in exact
// contact.
//
// All runs use Shi's DDA integrator, as DDA codes do: with Newmark the
// unresolved vibration of the stiff contact springs is not damped and makes
// the contacts chatter (doc/contact.md, "Known limits").
//
//  - friction angle 20 degrees: the block slides; along the slope it moves
//    s(t) = g (sin a - cos a tan phi) t^2 / 2, checked to 0.5 % at t = 1 s
//    for time steps 1e-4, 5e-4 and 2e-3 s;
//  - frictionless: s(t) = g sin a t^2 / 2, checked to 0.1 %;
//  - friction angle 35 degrees: the block sticks; its creep in 1 s must stay
//    below 0.1 mm for penalties 10 E, 100 E and 1000 E;
//  - the slide (dt 5e-4) and the stick again, meshed and rigid, with
//    lagged friction (penalty Coulomb's Lagged friction: Shi's DDA's
//    friction from the normal force of the solve before): the same targets.
//
// In every run no contact may penetrate deeper than the scene's tolerance
// (Contact/Maximum penetration ratio of half the scene height). The
// measured errors are printed.

#include <deal.II/base/timer.h>

#include <cmath>

#include "tests.h"

using namespace ndda_tests;

namespace
{
  const double slope = 30. * M_PI / 180.;
  const double g     = 9.81;

  /** A point at distance s along the slope and h above it. */
  std::string
  at(const double s, const double h)
  {
    return point_on_slope(slope, s, h);
  }

  const std::string scene = R"(
subsection Control
  set Analysis type   = dynamic
  set Time integrator = {integrator}
  set Time step       = {dt}
  set End time        = 1
  set Maximum displacement ratio = 0.01
  set Kinematics = {model}
end
subsection Contact
  set Penalty factor = {penalty}
  set Maximum penetration ratio = 1e-3
  subsection penalty Coulomb
    set Lagged friction = {lagged}
  end
end
subsection Materials
  set Names = rock
  subsection rock
    set Density = 2600
    set Young's modulus = 10e9
    set Poisson's ratio = 0.25
  end
  subsection Joint
    set Friction angle = {phi}
  end
end
subsection Geometry
  set Blocks = incline, block
  subsection incline
    set Outer boundary = 0, 0; {base_x}, 0; {base_top}
    set Material = rock
    set Mesh size = 0.5
  end
  subsection block
    set Outer boundary = {b0}; {b1}; {b2}; {b3}
    set Material = rock
    set Mesh size = 0.25
  end
end
subsection Loads
  set Gravity = 0; -9.81
end
subsection Boundary conditions
  set Names = ground
  subsection ground
    set Type = fixed
    set Segments = 0, 0, {base_x}, 0; {base_x}, 0, {base_top_comma}
  end
end
subsection Output
  set Measure points = {centre}
end
)";

  struct Result
  {
    double       displacement; // along the slope, downwards positive
    double       max_penetration;
    double       tolerance;
    double       seconds;
    unsigned int steps, iterations, cuts;
  };

  Result
  run(const std::string &integrator,
      const double       dt,
      const double       phi,
      const double       penalty,
      const std::string &model  = "meshed",
      const bool         lagged = false)
  {
    const double      length = 5.; // slope length
    const double      base_x = length * std::cos(slope);
    const double      s0 = 3.5, w = 1., h = 0.5; // block position and size
    const std::string top       = at(length, 0);
    std::string       top_comma = top;
    const auto        parameters =
      read_parameters(substitute(scene,
                                 {{"model", model},
                                  {"lagged", lagged ? "true" : "false"},
                                  {"integrator", integrator},
                                  {"dt", std::to_string(dt)},
                                  {"penalty", std::to_string(penalty)},
                                  {"phi", std::to_string(phi)},
                                  {"base_x", std::to_string(base_x)},
                                  {"base_top", top},
                                  {"base_top_comma", top_comma},
                                  {"b0", at(s0, 0)},
                                  {"b1", at(s0 + w, 0)},
                                  {"b2", at(s0 + w, h)},
                                  {"b3", at(s0, h)},
                                  {"centre", at(s0 + w / 2, h / 2)}}),
                      "sliding_block");
    ndda::Simulator<2> simulator(parameters);
    dealii::Timer      timer;
    simulator.setup();
    Result     result{};
    const auto box = simulator.get_mesh().bounding_box();
    result.tolerance =
      1e-3 * 0.5 * (box.second[1] - box.first[1]); // as the Simulator's
    while (simulator.get_time() < 1 - 1e-12)
      {
        simulator.do_time_step();
        const auto &c = simulator.get_contacts().get_statistics();
        result.max_penetration =
          std::max(result.max_penetration, c.max_penetration);
        result.iterations += c.n_iterations;
      }
    result.seconds = timer.wall_time();
    result.steps   = simulator.get_step_number();
    const auto &u  = simulator.get_measure_histories()[0].back().displacement;
    result.displacement = -(u[0] * std::cos(slope) + u[1] * std::sin(slope));
    return result;
  }
} // namespace

int
main(int argc, char **argv)
{
  using namespace dealii;
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::cout << std::setprecision(4);

  const auto report =
    [](const std::string &what, const Result &r, const std::string &key) {
      record(key + "iterations", double(r.iterations) / r.steps, 3);
      record(key + "penetration", r.max_penetration, 1);
      record(key + "tolerance", r.tolerance, 2);
      std::cout << "    " << what << ": " << r.steps << " steps, "
                << double(r.iterations) / r.steps
                << " open-close iterations per step, max penetration "
                << r.max_penetration << " m (tolerance " << r.tolerance
                << " m), " << r.seconds << " s" << std::endl;
      check(r.max_penetration <= r.tolerance, what + ": penetration");
    };

  // Sliding with friction.
  const double phi = 20. * M_PI / 180.;
  const double expected =
    0.5 * g * (std::sin(slope) - std::cos(slope) * std::tan(phi));
  std::cout << "friction angle 20 deg: expected slide " << expected
            << " m in 1 s" << std::endl;
  for (const double dt : {1e-4, 5e-4, 2e-3})
    {
      const Result r     = run("DDA", dt, 20, 100);
      const double error = r.displacement / expected - 1;
      std::cout << "  dt = " << dt << ": slide " << r.displacement
                << " m, error " << 100 * error << " %" << std::endl;
      const std::string key = "sliding_block.friction_" +
                              std::to_string(int(std::round(dt * 1e4))) + ".";
      record(key + "expected", expected, 4);
      record(key + "slide", r.displacement, 4);
      record(key + "error", 100 * error, 2);
      record(key + "met", met(std::abs(error) < 5e-3));
      report("friction, dt = " + std::to_string(dt), r, key);
      check(std::abs(error) < 5e-3, "sliding with friction within 0.5 %");
    }

  // Frictionless.
  const double free_slide = 0.5 * g * std::sin(slope);
  std::cout << "frictionless: expected slide " << free_slide << " m in 1 s"
            << std::endl;
  for (const auto &[integrator, dt] :
       std::vector<std::pair<std::string, double>>{{"DDA", 5e-4},
                                                   {"DDA", 2e-3}})
    {
      const Result r     = run(integrator, dt, 0, 100);
      const double error = r.displacement / free_slide - 1;
      std::cout << "  " << integrator << ", dt = " << dt << ": slide "
                << r.displacement << " m, error " << 100 * error << " %"
                << std::endl;
      const std::string key =
        "sliding_block.free_" + std::to_string(int(std::round(dt * 1e4))) + ".";
      record(key + "expected", free_slide, 5);
      record(key + "slide", r.displacement, 5);
      record(key + "error", 100 * error, 1);
      record(key + "met", met(std::abs(error) < 1e-3));
      report("frictionless, dt = " + std::to_string(dt), r, key);
      check(std::abs(error) < 1e-3, "frictionless sliding within 0.1 %");
    }

  // Sticking: tan 35 > tan 30.
  std::cout << "friction angle 35 deg: the block must stick" << std::endl;
  for (const double penalty : {10., 100., 1000.})
    {
      const Result r = run("DDA", 1e-3, 35, penalty);
      std::cout << "  penalty " << penalty << " E: creep " << r.displacement
                << " m" << std::endl;
      const std::string key =
        "sliding_block.stick_" + std::to_string(int(penalty)) + ".";
      record(key + "creep", r.displacement * 1e6, 2);
      record(key + "met", met(std::abs(r.displacement) < 1e-4));
      report("stick, penalty " + std::to_string(penalty), r, key);
      check(std::abs(r.displacement) < 1e-4, "creep below 0.1 mm");
    }

  // The same slide, frictionless slide and stick with the block and the
  // incline as affine (Shi's DDA blocks) and as rigid blocks: the same
  // targets.
  for (const std::string model : {"affine", "rigid"})
    {
      const Result slide      = run("DDA", 5e-4, 20, 100, model);
      const Result free       = run("DDA", 5e-4, 0, 100, model);
      const Result stick      = run("DDA", 1e-3, 35, 100, model);
      const double error      = slide.displacement / expected - 1;
      const double free_error = free.displacement / free_slide - 1;
      std::cout << model << ": slide " << slide.displacement << " m, error "
                << 100 * error << " %; frictionless " << free.displacement
                << " m, error " << 100 * free_error << " %; creep at 35 deg "
                << stick.displacement << " m" << std::endl;
      const std::string key = "sliding_block." + model + ".";
      record(key + "error", 100 * error, 2);
      record(key + "free_error", 100 * free_error, 1);
      record(key + "creep", stick.displacement * 1e6, 2);
      record(key + "ms_per_step", 1e3 * slide.seconds / slide.steps, 2);
      record(key + "met",
             met(std::abs(error) < 5e-3 && std::abs(free_error) < 1e-3 &&
                 std::abs(stick.displacement) < 1e-4));
      report(model + ", friction", slide, key + "friction.");
      report(model + ", frictionless", free, key + "free.");
      report(model + ", stick", stick, key + "stick.");
      check(std::abs(error) < 5e-3, model + ": sliding within 0.5 %");
      check(std::abs(free_error) < 1e-3, model + ": frictionless within 0.1 %");
      check(std::abs(stick.displacement) < 1e-4,
            model + ": creep below 0.1 mm");
    }

  // Lagged friction (Shi's DDA: the normal force of the solve before, the
  // matrix symmetric): the same slide and stick targets, meshed and rigid.
  for (const std::string model : {"meshed", "rigid"})
    {
      const Result slide = run("DDA", 5e-4, 20, 100, model, true);
      const Result stick = run("DDA", 1e-3, 35, 100, model, true);
      const double error = slide.displacement / expected - 1;
      std::cout << model << ", lagged friction: slide " << slide.displacement
                << " m, error " << 100 * error << " %; creep at 35 deg "
                << stick.displacement << " m" << std::endl;
      const std::string key = "sliding_block.lagged_" + model + ".";
      record(key + "error", 100 * error, 2);
      record(key + "creep", stick.displacement * 1e6, 2);
      record(key + "met",
             met(std::abs(error) < 5e-3 &&
                 std::abs(stick.displacement) < 1e-4));
      report(model + ", lagged friction", slide, key + "friction.");
      report(model + ", lagged friction, stick", stick, key + "stick.");
      check(std::abs(error) < 5e-3, model + ", lagged: sliding within 0.5 %");
      check(std::abs(stick.displacement) < 1e-4,
            model + ", lagged: creep below 0.1 mm");
    }
  std::cout << "OK" << std::endl;
}
