// SPDX-License-Identifier: GPL-3.0-or-later
//
// A 0.5 m x 0.5 m block dropped 0.5 m onto a fixed block (contact issue,
// second "must show" item), frictionless, one bounce (0.7 s):
//
//  - the first contact closes in the step that contains the impact time
//    sqrt(2 h / g), for both integrators;
//  - no contact penetrates deeper than the scene's tolerance;
//  - Newmark with a penalty that resolves the impact in time (0.01 E: the
//    contact lasts about 20 steps): no energy gain beyond 1 % of m g h at
//    any time, and the block rebounds to within 5 % of the drop height;
//  - DDA: no energy gain either; its restitution is reported;
//  - Newmark with a stiffer penalty (0.1 E, about 6 steps of contact) is
//    reported: it misses the energy target (printed, not asserted).
//
// Five bounces (Newmark, 0.01 E, the block meshed finer): no energy gain
// beyond 1 % of m g h at any time (asserted) and the five rebound heights
// (printed against the 5 % target, which is not met: doc/contact.md).
// The falling block as an affine and as a rigid block (issue 15): the same
// targets, all asserted, and the five bounces printed.

#include <cmath>

#include "tests.h"

using namespace ndda_tests;

namespace
{
  const std::string scene = R"(
subsection Control
  set Analysis type   = dynamic
  set Time integrator = {integrator}
  set Time step       = 1e-4
  set End time        = {end}
  set Maximum displacement ratio = 0.01
  set Matrix update tolerance = 0.05
end
subsection Contact
  set Penalty factor = {penalty}
  set Maximum penetration ratio = {tolerance}
end
subsection Materials
  set Names = rock
  subsection rock
    set Density = 2600
    set Young's modulus = 50e9
    set Poisson's ratio = 0.25
  end
  subsection Joint
    set Friction angle = 0
  end
end
subsection Geometry
  set Blocks = base, block
  subsection base
    set Outer boundary = -1, -0.5; 1, -0.5; 1, 0; -1, 0
    set Material = rock
    set Mesh size = 0.25
  end
  subsection block
    set Outer boundary = -0.25, 0.5; 0.25, 0.5; 0.25, 1; -0.25, 1
    set Material = rock
    set Mesh size = {block_mesh}
    set Kinematics = {model}
  end
end
subsection Loads
  set Gravity = 0; -9.81
end
subsection Boundary conditions
  set Names = ground
  subsection ground
    set Type = fixed
    set Segments = -1, -0.5, 1, -0.5
  end
end
subsection Output
  set Measure points = 0, 0.75
end
)";

  struct Result
  {
    double impact_step_end = -1; // time at the end of the first contact step
    double dt              = 0;
    double rebound         = 0; // largest height of the centre after impact
    double max_gain        = 0; // largest energy gain (J)
    double max_penetration = 0;
    double tolerance       = 0;
    double dissipation     = 0;
    std::vector<double> rebounds; // largest height after each impact
  };

  Result
  run(const std::string &integrator,
      const double       penalty,
      const double       tolerance_ratio,
      const double       end_time   = 0.7,
      const double       block_mesh = 0.5,
      const std::string &model      = "meshed")
  {
    const auto parameters = read_parameters(
      substitute(scene,
                 {{"integrator", integrator},
                  {"penalty", std::to_string(penalty)},
                  {"tolerance", std::to_string(tolerance_ratio)},
                  {"end", std::to_string(end_time)},
                  {"block_mesh", std::to_string(block_mesh)},
                  {"model", model}}),
      "block_drop");
    ndda::Simulator<2> simulator(parameters);
    simulator.setup();
    Result result;
    result.tolerance   = tolerance_ratio * 0.5 * 1.5; // half the scene height
    bool   was_closed  = false;
    double last_closed = -1.;
    while (simulator.get_time() < end_time - 1e-12)
      {
        simulator.do_time_step();
        const auto &c = simulator.get_contacts().get_statistics();
        // An impact: the first closed contact after at least 0.1 s of
        // flight (a contact may open and close again within one impact).
        if (c.n_closed > 0 && simulator.get_time() > last_closed + 0.1)
          result.rebounds.push_back(0.);
        if (c.n_closed > 0)
          last_closed = simulator.get_time();
        was_closed = c.n_closed > 0;
        if (result.impact_step_end < 0 && c.n_closed > 0)
          {
            result.impact_step_end = simulator.get_time();
            result.dt = simulator.get_parameters().control.time_step;
          }
        result.max_penetration =
          std::max(result.max_penetration, c.max_penetration);
        result.max_gain = std::max(result.max_gain, simulator.energy_error());
        result.dissipation = c.dissipation;
        const double height =
          simulator.get_measure_histories()[0].back().displacement[1] + 0.5;
        if (result.impact_step_end > 0 &&
            simulator.get_time() > result.impact_step_end + 0.01)
          result.rebound = std::max(result.rebound, height);
        if (!was_closed && !result.rebounds.empty())
          result.rebounds.back() = std::max(result.rebounds.back(), height);
      }
    return result;
  }
} // namespace

int
main(int argc, char **argv)
{
  using namespace dealii;
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::cout << std::setprecision(4);

  const double h = 0.5, g = 9.81, mass = 2600 * 0.25;
  const double impact = std::sqrt(2 * h / g);
  const double mgh    = mass * g * h;
  std::cout << "impact time sqrt(2 h / g) = " << impact << " s, m g h = " << mgh
            << " J" << std::endl;

  const auto check_common =
    [&](const std::string &what, const Result &r, const std::string &key) {
      record(key + "impact_step_end", r.impact_step_end, 5);
      record(key + "rebound", 100 * r.rebound / h, 3);
      record(key + "gain", r.max_gain / mgh, 2);
      record(key + "gain_percent", 100 * r.max_gain / mgh, 2);
      record(key + "penetration", r.max_penetration * 1e3, 3);
      record(key + "tolerance", r.tolerance * 1e3, 3);
      record(key + "dissipation_percent", 100 * r.dissipation / mgh, 2);
      record(key + "impact_met",
             met(r.impact_step_end - r.dt < impact + 1e-12 &&
                 impact <= r.impact_step_end + 1e-12 &&
                 r.max_penetration <= r.tolerance));
      record(key + "gain_met", met(r.max_gain <= 0.01 * mgh));
      std::cout << "  " << what << ": first contact in the step ending at "
                << r.impact_step_end << " s, rebound " << r.rebound << " m ("
                << 100 * r.rebound / h
                << " % of the drop), largest energy gain " << r.max_gain
                << " J (" << 100 * r.max_gain / mgh
                << " % of m g h), contacts dissipated " << r.dissipation
                << " J, max penetration " << r.max_penetration
                << " m (tolerance " << r.tolerance << " m)" << std::endl;
      check(r.impact_step_end - r.dt < impact + 1e-12 &&
              impact <= r.impact_step_end + 1e-12,
            what + ": impact not in the first contact step");
      check(r.max_penetration <= r.tolerance, what + ": penetration");
    };

  const Result newmark = run("Newmark", 0.01, 5e-3);
  check_common("Newmark, penalty 0.01 E", newmark, "block_drop.newmark.");
  record("block_drop.newmark.rebound_met",
         met(std::abs(newmark.rebound / h - 1) < 0.05));
  check(newmark.max_gain <= 0.01 * mgh, "Newmark: energy gain beyond 1 %");
  check(std::abs(newmark.rebound / h - 1) < 0.05,
        "Newmark rebound not within 5 % of the drop height");

  const Result dda = run("DDA", 0.01, 5e-3);
  check_common("DDA, penalty 0.01 E", dda, "block_drop.dda.");
  record("block_drop.dda.restitution", std::sqrt(dda.rebound / h), 2);
  check(dda.max_gain <= 0.01 * mgh, "DDA: energy gain beyond 1 %");
  std::cout << "  DDA restitution sqrt(h1 / h) = " << std::sqrt(dda.rebound / h)
            << std::endl;

  // Not asserted: with the impact resolved by only about 6 steps the
  // energy target is missed (doc/contact.md, "Known limits").
  const Result stiff = run("Newmark", 0.1, 1e-3);
  check_common("Newmark, penalty 0.1 E", stiff, "block_drop.stiff.");
  if (stiff.max_gain > 0.01 * mgh)
    std::cout << "  target NOT met for penalty 0.1 E: energy gain "
              << 100 * stiff.max_gain / mgh << " % > 1 %" << std::endl;
  // Five bounces (3.3 s), the falling block meshed with 0.25 m cells.
  const Result five = run("Newmark", 0.01, 5e-3, 3.3, 0.25);
  check_common("Newmark, penalty 0.01 E, five bounces",
               five,
               "block_drop.five.");
  check(five.max_gain <= 0.01 * mgh,
        "Newmark, five bounces: energy gain beyond 1 %");
  check(five.rebounds.size() >= 5, "fewer than five bounces in 3.3 s");
  double worst = 0;
  std::cout << "  rebound / drop height:";
  for (unsigned int k = 0; k < 5; ++k)
    {
      std::cout << " " << 100 * five.rebounds[k] / h << " %";
      worst = std::max(worst, std::abs(five.rebounds[k] / h - 1));
    }
  std::cout << std::endl;
  // The five rebounds in % of the drop height, and how many of them in a
  // row are within 5 % of it.
  const auto record_rebounds = [&](const Result &r, const std::string &key) {
    std::ostringstream list;
    list << std::setprecision(3);
    unsigned int within = 0;
    for (unsigned int k = 0; k < 5; ++k)
      {
        list << (k > 0 ? ", " : "") << 100 * r.rebounds[k] / h;
        if (std::abs(r.rebounds[k] / h - 1) <= 0.05 && within == k)
          ++within;
      }
    record(key + "rebounds", list.str());
    record(key + "rebounds_met",
           within == 5 ? "met" :
                         "**met for the first " + std::to_string(within) +
                           " bounces only**");
    return list.str();
  };
  record_rebounds(five, "block_drop.five.");
  // Not asserted: the block's elastic vibration, excited at each impact
  // and undamped by Newmark, takes up to 8 % of m g h (doc/contact.md).
  if (worst > 0.05)
    std::cout << "  target NOT met: a rebound differs by " << 100 * worst
              << " % from the drop height (target 5 %)" << std::endl;

  // The falling block as Shi's DDA block and as a rigid block (the base
  // stays meshed and fixed): the same targets as the meshed block's, and
  // the five bounces, where a block without a mesh has no vibration to
  // take energy from the bounce.
  for (const std::string model : {"affine", "rigid"})
    {
      const std::string key = "block_drop." + model + ".";
      const Result      n   = run("Newmark", 0.01, 5e-3, 0.7, 0.5, model);
      check_common(model + ", Newmark, penalty 0.01 E", n, key + "newmark.");
      record(key + "newmark.rebound_met",
             met(std::abs(n.rebound / h - 1) < 0.05));
      check(n.max_gain <= 0.01 * mgh, model + ", Newmark: energy gain");
      check(std::abs(n.rebound / h - 1) < 0.05,
            model + ", Newmark: rebound not within 5 % of the drop height");
      const Result d = run("DDA", 0.01, 5e-3, 0.7, 0.5, model);
      check_common(model + ", DDA, penalty 0.01 E", d, key + "dda.");
      record(key + "dda.restitution", std::sqrt(d.rebound / h), 2);
      check(d.max_gain <= 0.01 * mgh, model + ", DDA: energy gain");
      const Result f = run("Newmark", 0.01, 5e-3, 3.3, 0.25, model);
      check_common(model + ", Newmark, five bounces", f, key + "five.");
      check(f.max_gain <= 0.01 * mgh,
            model + ", five bounces: energy gain beyond 1 %");
      check(f.rebounds.size() >= 5,
            model + ": fewer than five bounces in 3.3 s");
      const std::string rebounds = record_rebounds(f, key + "five.");
      std::cout << "  " << model
                << ", five bounces, rebound / drop height (%): " << rebounds
                << std::endl;
    }
  std::cout << "OK" << std::endl;
}
