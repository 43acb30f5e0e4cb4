// SPDX-License-Identifier: GPL-3.0-or-later
//
// Values that are not finite (issue 17, "silent NaN"): a scene whose
// expressions divide by zero or leave their domain must stop with a
// message that names the entry, not run to its end writing NaN.
//  1. A gravity history that is infinite at t = 0.5 s of a 1 s run is
//     refused at setup (--validate evaluates every component of every
//     expression at 65 times over the run), naming the entry, the
//     component and the time.
//  2. An error in the second component of a point load's force (muparser
//     parses a component only when it evaluates it) is refused when the
//     parameters are read, naming the entry and the component.
//  3. A gravity history that is NaN only between two of the setup's
//     sample times stops the run at the step that evaluates it; the
//     steps before it are kept (the time stays at the last good step).
//  4. An initial velocity that divides by zero at a node, and a
//     prescribed displacement that takes the log of a negative number at
//     the start, are refused at setup, naming their entries.
// Printed: the messages.

#include "tests.h"

using namespace ndda_tests;

namespace
{
  const std::string scene = R"(
subsection Control
  set Time step = 1e-3
  set End time  = 1
end
subsection Materials
  set Names = rock
  subsection rock
    set Density         = 2500
    set Young's modulus = 1e9
    set Poisson's ratio = 0.25
  end
end
subsection Geometry
  set Blocks = slab
  subsection slab
    set Outer boundary   = 0, 0; 1, 0; 1, 1; 0, 1
    set Material         = rock
    set Mesh size        = 0.5
    set Initial velocity = {velocity}
  end
end
subsection Boundary conditions
  set Names = base
  subsection base
    set Type     = displacement
    set Segments = 0, 0, 1, 0
    set Value    = {base}
  end
end
subsection Loads
  set Gravity     = {gravity}
  set Point loads = push
  subsection push
    set Point = 1, 1
    set Force = {force}
  end
end
)";

  std::string
  make_scene(const std::map<std::string, std::string> &changes)
  {
    std::map<std::string, std::string> values = {{"velocity", "0; 0"},
                                                 {"base", "0; 0"},
                                                 {"gravity", "0; -9.81"},
                                                 {"force", "0; 0"}};
    for (const auto &[key, value] : changes)
      values[key] = value;
    return substitute(scene, values);
  }

  /** The message of setting up the scene with @p changes; empty if none. */
  std::string
  setup_message(const std::map<std::string, std::string> &changes)
  {
    return message_of([&]() {
      ndda::Simulator<2> simulator(
        read_parameters(make_scene(changes), "nan_guards"));
      simulator.setup();
    });
  }

  void
  expect(const std::string              &what,
         const std::string              &message,
         const std::vector<std::string> &phrases)
  {
    std::cout << what << ": " << message << std::endl;
    for (const auto &phrase : phrases)
      check(message.find(phrase) != std::string::npos,
            what + ": the message names '" + phrase + "'");
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  check(setup_message({}).empty(), "the scene itself sets up");

  // 1.
  expect("gravity infinite at t = 0.5 s",
         setup_message({{"gravity", "0; -9.81 / (t - 0.5)"}}),
         {"Loads/Gravity", "component 2", "-inf", "t = 0.5 s"});

  // 2.
  expect("second component not valid",
         message_of([]() {
           read_parameters(make_scene({{"force", "1000 * t; -500 * z"}}),
                           "nan_guards");
         }),
         {"Loads/push/Force", "component 2", "not a valid function"});

  // 3.
  {
    ndda::Simulator<2> simulator(read_parameters(
      make_scene(
        {{"gravity", "0; if(t > 0.3001 & t < 0.302, sqrt(-1), -9.81)"}}),
      "nan_guards"));
    simulator.setup();
    std::string message;
    while (message.empty() && simulator.get_time() < 1 - 1e-12)
      message = message_of([&]() { simulator.do_time_step(); });
    expect("gravity NaN between the sample times",
           message,
           {"Loads/Gravity", "component 2", "nan", "t = 0.301 s"});
    std::cout << "the run stopped at t = " << simulator.get_time() << " s"
              << std::endl;
    check(std::abs(simulator.get_time() - 0.3) < 1e-9,
          "the run keeps the last good step (t = 0.3 s)");
  }

  // 4.
  expect("initial velocity 1/x",
         setup_message({{"velocity", "1 / x; 0"}}),
         {"Geometry/slab/Initial velocity", "component 1", "inf"});
  expect("prescribed displacement log(t - 0.25)",
         setup_message({{"base", "0; log(t - 0.25)"}}),
         {"Boundary conditions/base/Value", "component 2", "nan", "t = 0 s"});
  std::cout << "OK" << std::endl;
}
