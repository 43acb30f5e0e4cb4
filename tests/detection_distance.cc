// SPDX-License-Identifier: GPL-3.0-or-later
//
// The detection distance (issue 15; doc/contact.md, "Detection"),
// `Contact/Detection distance = scene | motion`.
//
// 1. contact::DetectionDistance on its own: the rule `scene` is Shi's
//    distance in every step; the rule `motion` starts at the floor (1 % of
//    Shi's), follows four times the last step's largest increment (scaled
//    by the square of a growing step), shrinks by at most 10 % a step,
//    adds twice the deepest contact, is widened (to four times the
//    attempt's increment, at most Shi's) when an attempt moves further
//    than it covers, and covers
//    everything at Shi's distance.
// 2. A block thrown down onto a fixed base (0.5 m square, 2 cm above the
//    base, 2 m/s down, gravity, DDA, dt = 1 ms, 0.1 s: it lands and
//    bounces), run with both rules. Checked: the rule `motion` widens the
//    first step's distance (its first attempt moves 2 mm, beyond the
//    floor's reach; the base is not in reach, so it is not solved again), lists
//    fewer candidates over the run (the base is found when the block is a few
//    steps away, not 1.5 cm), and ends where the rule `scene` ends: the block's
//    centre within 1e-9 m, the same largest penetration within 1e-9 m, the same
//    closed contacts in every step.
// 3. Vertex-vertex example 2 (prm/vertex_vertex_2.prm) with the
//    shortest-path rule, run with both rules: the same closed contacts in
//    every step and the falling vertex's end position within 1e-9 m. With
//    Shi's 0.26 m the falling corner resting on the apex was also a
//    vertex-vertex pair with the next vertex down the slope, 0.2 m away,
//    and the two rules ended 2 cm apart (doc/contact.md, "The contacts do
//    not depend on the distance").

#include <deal.II/base/mpi.h>

#include <ndda/contact/detection_distance.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <regex>

#include "tests.h"

using namespace ndda_tests;

namespace
{
  void
  test_rule()
  {
    using ndda::contact::DetectionDistance;
    std::cout << "1. DetectionDistance" << std::endl;
    const double      full = 0.1;
    DetectionDistance scene;
    scene.initialize(DetectionDistance::Rule::scene, full);
    check(scene.for_step(1e-3) == full, "scene: Shi's distance");
    check(scene.covers(0.05) && scene.covers(1.), "scene: covers anything");
    check(scene.skin() == 0., "scene: the list's own skin");

    DetectionDistance motion;
    motion.initialize(DetectionDistance::Rule::motion, full);
    const double floor = DetectionDistance::floor_fraction * full;
    check(motion.for_step(1e-3) == floor, "motion: starts at the floor");
    check(motion.covers(0.5 * floor) && !motion.covers(0.6 * floor),
          "motion: covers half the distance");
    const double widened = motion.widen(0.6 * floor);
    check(std::abs(widened - 4. * 0.6 * floor) < 1e-15 &&
            motion.get() == widened,
          "motion: widened to four times the attempt's increment");
    check(motion.widen(0.02) == 4. * 0.02, "motion: widened to the motion");
    check(motion.widen(1.) == full && motion.covers(1.),
          "motion: at most Shi's, which covers anything");
    check(motion.n_widenings() == 3, "motion: widenings counted");
    motion.accept(1e-3, 0.005, 0.);
    check(std::abs(motion.for_step(1e-3) - 0.9 * full) < 1e-15,
          "motion: shrinks by at most 10 % a step");
    for (unsigned int i = 0; i < 20; ++i)
      motion.for_step(1e-3);
    check(std::abs(motion.get() - 4. * 0.005) < 1e-15,
          "motion: four times the last step's increment");
    check(std::abs(motion.for_step(2e-3) - 16. * 0.005) < 1e-15,
          "motion: a doubled step four times that");
    motion.accept(2e-3, 1e-6, 0.003);
    for (unsigned int i = 0; i < 100; ++i)
      motion.for_step(2e-3);
    check(std::abs(motion.get() - (floor + 2. * 0.003)) < 1e-15,
          "motion: the floor and twice the deepest contact");
    std::cout << "  passed" << std::endl;
  }



  struct Result
  {
    ndda::Point<2>            centre;
    double                    max_penetration = 0;
    unsigned long             candidates      = 0;
    unsigned int              widenings       = 0;
    std::vector<unsigned int> closed;
  };

  Result
  run_scene(const ndda::parameters::Parameters &parameters,
            const std::string                  &name);



  Result
  run(const std::string &rule)
  {
    const auto parameters = read_parameters(substitute(R"(
subsection Control
  set Analysis type   = dynamic
  set Time integrator = DDA
  set Time step       = 1e-3
  set End time        = 0.1
end
subsection Contact
  set Penalty factor     = 10
  set Detection distance = {rule}
end
subsection Materials
  set Names = rock
  subsection rock
    set Density = 2600
    set Young's modulus = 10e9
    set Poisson's ratio = 0.25
  end
  subsection Joint
    set Friction angle = 30
  end
end
subsection Geometry
  set Blocks = base, block
  subsection base
    set Outer boundary = -1, -0.5; 1, -0.5; 1, 0; -1, 0
    set Material = rock
    set Mesh size = 0.5
  end
  subsection block
    set Outer boundary = -0.25, 0.02; 0.25, 0.02; 0.25, 0.52; -0.25, 0.52
    set Material = rock
    set Mesh size = 0.25
    set Initial velocity = 0; -2
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
  set Write vtu      = false
  set Measure points = 0, 0.27
end
)",
                                                       {{"rule", rule}}),
                                            "detection_distance_" + rule);
    return run_scene(parameters, rule);
  }



  /** Run @p parameters to their end time, recording under @p name. */
  Result
  run_scene(const ndda::parameters::Parameters &parameters,
            const std::string                  &name)
  {
    ndda::Simulator<2> simulator(parameters);
    simulator.setup();
    Result result;
    while (simulator.get_time() < parameters.control.end_time - 1e-12)
      {
        simulator.do_time_step();
        const auto &c = simulator.get_contacts().get_statistics();
        result.candidates += c.n_contacts;
        result.closed.push_back(c.n_closed);
        result.max_penetration =
          std::max(result.max_penetration, c.max_penetration);
      }
    result.centre = parameters.output.measure_points[0] +
                    simulator.get_measure_histories()[0].back().displacement;
    result.widenings = simulator.get_detection_distance().n_widenings();
    std::cout << "  " << name << ": point " << result.centre
              << ", candidates over the run " << result.candidates
              << ", distance widened " << result.widenings
              << ", largest penetration " << result.max_penetration << " m"
              << std::endl;
    return result;
  }



  void
  test_drop()
  {
    std::cout << "2. A block thrown onto a base" << std::endl;
    const Result scene  = run("scene");
    const Result motion = run("motion");
    check(scene.widenings == 0, "scene: never detected again");
    check(motion.widenings >= 1, "motion: the first step's distance widened");
    check(motion.candidates < scene.candidates, "motion: fewer candidates");
    check(motion.centre.distance(scene.centre) < 1e-9,
          "motion: the same end position");
    check(std::abs(motion.max_penetration - scene.max_penetration) < 1e-9,
          "motion: the same largest penetration");
    check(motion.closed == scene.closed,
          "motion: the same closed contacts in every step");
    check(*std::max_element(scene.closed.begin(), scene.closed.end()) > 0,
          "the block lands");
    std::cout << "  passed" << std::endl;
  }



  void
  test_vertex_vertex()
  {
    std::cout << "3. Vertex-vertex example 2, shortest path" << std::endl;
    std::map<std::string, Result> results;
    for (const std::string rule : {"scene", "motion"})
      {
        std::string text = set_entry(read_example("vertex_vertex_2"),
                                     "Vertex-vertex method",
                                     "shortest path");
        text             = std::regex_replace(text,
                                  std::regex("subsection Contact\n"),
                                  "subsection Contact\n  set Detection "
                                              "distance = " +
                                    rule + "\n");
        text             = std::regex_replace(text,
                                  std::regex("subsection Output\n"),
                                  "subsection Output\n  set Write vtu = "
                                              "false\n");
        results[rule] =
          run_scene(read_parameters(text,
                                    "detection_distance_vertex_vertex_" + rule),
                    rule);
      }
    const Result &scene = results["scene"], &motion = results["motion"];
    check(motion.candidates < scene.candidates, "motion: fewer candidates");
    check(motion.closed == scene.closed,
          "motion: the same closed contacts in every step");
    check(motion.centre.distance(scene.centre) < 1e-9,
          "motion: the falling vertex ends at the same position");
    std::cout << "  passed" << std::endl;
  }
} // namespace



int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  test_rule();
  test_drop();
  test_vertex_vertex();
}
