// SPDX-License-Identifier: GPL-3.0-or-later
//
// Rigid-body motion of a free block.
//
// Free fall: under gravity g, both integrators must give the position
// y(t) = -g t^2 / 2 exactly up to round-off: a uniform acceleration is
// integrated exactly by both schemes, and a translation makes no strain.
//
// Free rotation: a square spinning at omega about its centre. With the
// small-rotation (linear) update every step moves points along the tangent,
// so the block grows: with theta = omega dt, the scale s obeys
// s_{n+1}^2 = s_n^2 + theta^2, i.e. after N steps the area is
// (1 + N theta^2) times the initial area (doc/theory.md). The test reports
// the measured area change after one turn's time, checks it against this
// prediction, and checks that it halves when the step is halved.

#include <cmath>

#include "tests.h"

using namespace ndda_tests;

const std::string scene = R"(
subsection Control
  set Analysis type   = dynamic
  set Time integrator = {integrator}
  set Time step       = {dt}
  set End time        = {end}
  set Maximum displacement ratio = 0.5
end
subsection Materials
  set Names = rock
  subsection rock
    set Density = 2000
    set Young's modulus = 1e9
    set Poisson's ratio = 0.2
  end
end
subsection Geometry
  set Blocks = block
  subsection block
    set Outer boundary = -0.5, -0.5; 0.5, -0.5; 0.5, 0.5; -0.5, 0.5
    set Material = rock
    set Mesh size = 0.2
    set Initial velocity = {velocity}
  end
end
subsection Loads
  set Gravity = 0; {g}
end
subsection Output
  set Measure points = 0.5, 0
end
)";

namespace
{
  /** The additional information of a deal.II exception on one line, from
   * its "Step N" on (deal.II wraps the text). */
  std::string
  error_message(const std::exception &e)
  {
    const std::string text = e.what();
    const std::size_t step = text.find("Step ");
    const std::string line =
      fold_whitespace(text.substr(step == std::string::npos ? 0 : step));
    return line.substr(0, line.find(" Stacktrace:"));
  }
} // namespace

int
main(int argc, char **argv)
{
  using namespace dealii;
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  for (const std::string integrator : {"Newmark", "DDA"})
    {
      auto               parameters = read_parameters(substitute(scene,
                                                   {{"integrator", integrator},
                                                                  {"dt", "0.01"},
                                                                  {"end", "1"},
                                                                  {"velocity", "0; 0"},
                                                                  {"g", "-9.81"}}),
                                        "free_fall");
      ndda::Simulator<2> simulator(parameters);
      simulator.setup();
      double worst = 0;
      while (simulator.get_time() < 1 - 1e-12)
        {
          simulator.do_time_step();
          const double t      = simulator.get_time();
          const auto  &sample = simulator.get_measure_histories()[0].back();
          worst =
            std::max({worst,
                      std::abs(sample.displacement[1] + 0.5 * 9.81 * t * t),
                      std::abs(sample.displacement[0])});
        }
      std::cout << "free fall, " << integrator
                << ": largest position error over 100 steps " << std::scientific
                << std::setprecision(2) << worst << " m (fall height "
                << std::defaultfloat << 0.5 * 9.81 << " m)" << std::endl;
      // Round-off accumulates over the steps: the velocity update subtracts
      // nearly equal numbers (d and dt v0), and the rigid-body part of the
      // solution is set by the small mass term of K + c M. The bound is
      // 1e-9 of the fall height for 100 steps.
      const std::string key = "free_fall_rotation." + integrator + ".";
      record(key + "fall_error", worst, 2);
      record(key + "fall_relative", worst / (0.5 * 9.81), 2);
      record(key + "fall_met", met(worst < 1e-9 * 0.5 * 9.81));
      check(worst < 1e-9 * 0.5 * 9.81, "free fall not exact to round-off");
    }

  const double omega           = 2 * M_PI; // one turn per second
  double       previous_change = 0;
  for (const double dt : {2e-3, 1e-3})
    {
      auto parameters =
        read_parameters(substitute(scene,
                                   {{"integrator", "Newmark"},
                                    {"dt", std::to_string(dt)},
                                    {"end", "1"},
                                    {"velocity",
                                     "-" + std::to_string(omega) + "*y; " +
                                       std::to_string(omega) + "*x"},
                                    {"g", "0"}}),
                        "free_rotation");
      ndda::Simulator<2> simulator(parameters);
      simulator.setup();
      const double area0 = simulator.get_mesh().area();
      while (simulator.get_time() < 1 - 1e-12)
        simulator.do_time_step();
      const double change    = simulator.get_mesh().area() / area0 - 1;
      const double theta     = omega * dt;
      const double n         = simulator.get_step_number();
      const double predicted = n * theta * theta;
      // Angle turned by the point that started at (0.5, 0).
      const auto  &u = simulator.get_measure_histories()[0].back();
      const double angle =
        std::atan2(u.displacement[1], 0.5 + u.displacement[0]);
      std::cout << "free rotation, dt = " << dt << ": area change after one "
                << "turn's time " << 100 * change << " % (linear-update "
                << "prediction N theta^2 = " << 100 * predicted
                << " %), end angle " << angle * 180 / M_PI
                << " deg, kinetic energy ratio "
                << simulator.kinetic_energy() /
                     (0.5 * 2000 * omega * omega / 6.)
                << std::endl;
      const std::string key = "free_fall_rotation.dt" +
                              std::to_string(int(std::round(dt * 1e3))) + "ms.";
      record(key + "area_change", 100 * change, 3);
      record(key + "predicted", 100 * predicted, 3);
      record(key + "angle", angle * 180 / M_PI, 3);
      record(key + "kinetic_ratio",
             simulator.kinetic_energy() / (0.5 * 2000 * omega * omega / 6.),
             4);
      record(key + "prediction_met",
             met(std::abs(change / predicted - 1) < 0.05));
      if (previous_change > 0)
        {
          record("free_fall_rotation.halving", change / previous_change, 3);
          record("free_fall_rotation.halving_met",
                 met(std::abs(change / previous_change - 0.5) < 0.05));
        }
      check(std::abs(change / predicted - 1) < 0.05,
            "area change differs from the linear-update prediction");
      if (previous_change > 0)
        check(std::abs(change / previous_change - 0.5) < 0.05,
              "area change is not first order in the step size");
      previous_change = change;
    }

  // A step that would turn cells inside out: a soft strip 0.2 m wide and
  // 1 m tall (E = 1e5 Pa, P-wave speed 7 m/s) squeezed sideways at the
  // strain rate -1000/s, Newmark with a nominal step of 10 ms. The inertia
  // term dominates, so a step moves the points by about v dt = -1000 x dt:
  // every cell turns over unless dt < 1 ms, while the displacement limit
  // (ratio 1: 0.5 m) allows 5 ms. The strip then collapses (it has almost
  // no stiffness), so the run may stop with an error; no accepted step may
  // leave a cell inside out.
  {
    std::string text = substitute(scene,
                                  {{"integrator", "Newmark"},
                                   {"dt", "0.01"},
                                   {"end", "0.01"},
                                   {"velocity", "-1000*x; 0"},
                                   {"g", "0"}});
    for (const auto &[from, to] :
         std::vector<std::pair<std::string, std::string>>{
           {"Maximum displacement ratio = 0.5",
            "Maximum displacement ratio = 1\n  set Maximum step cuts = 30"},
           {"Young's modulus = 1e9", "Young's modulus = 1e5"},
           {"-0.5, -0.5; 0.5, -0.5; 0.5, 0.5; -0.5, 0.5",
            "-0.1, -0.5; 0.1, -0.5; 0.1, 0.5; -0.1, 0.5"},
           {"Measure points = 0.5, 0", "Measure points = 0.1, 0"}})
      text.replace(text.find(from), from.size(), to);
    ndda::Simulator<2> simulator(read_parameters(text, "inversion"));
    simulator.setup();
    double      first_dt = 0, smallest = 1e9;
    std::string message = "none";
    try
      {
        while (simulator.get_time() < 0.01 - 1e-12)
          {
            simulator.do_time_step();
            if (first_dt == 0)
              first_dt = simulator.get_time();
            const auto &m = simulator.get_mesh().get_block_mesh();
            for (const auto &t : m.triangles)
              {
                const auto a = m.vertices[t[1]] - m.vertices[t[0]];
                const auto b = m.vertices[t[2]] - m.vertices[t[0]];
                smallest     = std::min(smallest, a[0] * b[1] - a[1] * b[0]);
              }
          }
      }
    catch (const std::exception &e)
      {
        message = error_message(e);
      }
    std::cout << "squeezed soft block: first step " << first_dt
              << " s (nominal 0.01 s), " << simulator.get_step_number()
              << " steps to t = " << simulator.get_time()
              << " s, smallest twice cell area " << smallest
              << " m^2; stopped by: " << message << std::endl;
    record("free_fall_rotation.inversion_first_dt", first_dt * 1e3, 3);
    record("free_fall_rotation.inversion_steps", simulator.get_step_number());
    record("free_fall_rotation.inversion_time", simulator.get_time() * 1e3, 3);
    record("free_fall_rotation.inversion_smallest", smallest, 3);
    check(first_dt > 0 && first_dt < 1e-3 && smallest > 0,
          "no accepted step turns a cell inside out");
  }

  // A run that crawls: a block moving at 1 m/s whose increments may not
  // exceed 2e-5 of half its height (1e-5 m), at a nominal step of 1 s.
  // Every step starts at twice the last one and is cut once, to 7.6 us,
  // far above the 1e-6 limit of the cuts; the run must stop after 1000
  // such steps in a row (doc/contact.md, 'Known limits').
  {
    std::string       text  = substitute(scene,
                                  {{"integrator", "DDA"},
                                          {"dt", "1"},
                                          {"end", "1"},
                                          {"velocity", "1; 0"},
                                          {"g", "0"}});
    const std::string ratio = "Maximum displacement ratio = 0.5";
    text.replace(text.find(ratio),
                 ratio.size(),
                 "Maximum displacement ratio = 2e-5\n"
                 "  set Maximum step cuts = 30");
    ndda::Simulator<2> simulator(read_parameters(text, "crawl"));
    simulator.setup();
    std::string message;
    try
      {
        while (simulator.get_time() < 1 - 1e-12)
          simulator.do_time_step();
      }
    catch (const std::exception &e)
      {
        message = error_message(e);
      }
    std::cout << "crawling run: stopped after " << simulator.get_step_number()
              << " steps at t = " << simulator.get_time() << " s" << std::endl;
    record("free_fall_rotation.crawl_steps", simulator.get_step_number());
    record("free_fall_rotation.crawl_time", simulator.get_time(), 3);
    check(message.find("the run crawls") != std::string::npos,
          "a run whose every step is cut far below the nominal step stops");
    check(simulator.get_step_number() == 1000,
          "the crawling run stops after 1000 steps");
  }
  std::cout << "OK" << std::endl;
}
