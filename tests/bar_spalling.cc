// SPDX-License-Identifier: GPL-3.0-or-later
//
// Spalling in the thesis's bar (fracture issue, "must show"; thesis 7.2.3,
// Table 1): prm/bar_spalling.prm, a 35 MPa sin^2 pulse of 40 us into the
// 1 m bar, tensile strength 18 MPa.
//
// 1. Where and when the first edge fails: Newmark (no numerical damping,
//    so the pulse keeps its height), detection only (Fracture/Split edges
//    = false). Reference: d'Alembert's solution for the bar speed
//    c = sqrt(E / rho) (plane stress), with xi the distance from the free
//    end and tau the time since the pulse front reached it,
//        sigma(xi, tau) = p(tau - xi / c) - p(tau + xi / c),
//    searched for the earliest tau at which some xi reaches 18 MPa. The
//    fracture check of each step interpolates the failure time within the
//    step.
// 2. The spall: the scene as it is (DDA integrator, as the thesis; edges
//    split). The crack runs through the section, the bar becomes two
//    blocks, the end piece (measure point at 0.97 m) leaves with a
//    positive velocity and its stress rings down towards zero.

#include <cmath>

#include "tests.h"

using namespace ndda_tests;

int
main(int argc, char **argv)
{
  using namespace dealii;
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::cout << std::setprecision(4);

  // The reference.
  const double E = 50e9, rho = 2600, P = 35e6, T = 18e6, pulse = 4e-5, L = 1.;
  const double c = std::sqrt(E / rho);
  const auto   p = [&](const double s) {
    return (s > 0 && s < pulse) ? P * std::pow(std::sin(M_PI * s / pulse), 2) :
                                    0.;
  };
  double tau = 0, xi = 0;
  for (bool found = false; !found && tau < 2 * pulse; tau += 1e-9)
    for (xi = 0; xi < 0.2; xi += 1e-5)
      if (p(tau - xi / c) - p(tau + xi / c) >= T)
        {
          found = true;
          break;
        }
  const double expected_time = L / c + tau;
  std::cout << "d'Alembert: first failure at " << expected_time * 1e6 << " us, "
            << xi * 1e3 << " mm from the free end" << std::endl;
  const std::string key = "bar_spalling.";
  record(key + "expected_time", expected_time * 1e6, 4);
  record(key + "expected_distance", xi * 1e3, 3);

  {
    std::string text = read_example("bar_spalling");
    text += "subsection Control\n  set End time = 2.7e-4\n"
            "  set Time integrator = Newmark\nend\n"
            "subsection Output\n  set Interval = 0\nend\n"
            "subsection Fracture\n  set Split edges = false\nend\n";
    const auto         parameters = read_parameters(text, "bar_spalling");
    ndda::Simulator<2> simulator(parameters);
    simulator.keep_measure_histories(); // the whole history
    simulator.setup();
    while (simulator.get_time() < 2.7e-4 - 1e-12)
      simulator.do_time_step();
    const auto &failure = simulator.get_first_edge_failure();
    check(failure.mode != ndda::fracture::FailureMode::none,
          "an edge fails before 270 us");
    const double distance = L - failure.location[0];
    std::cout << "Newmark, detection: first failure at " << failure.time * 1e6
              << " us, " << distance * 1e3 << " mm from the free end ("
              << (failure.mode == ndda::fracture::FailureMode::tension ?
                    "tension" :
                    "shear")
              << "); errors " << (failure.time - expected_time) * 1e6 << " us, "
              << (distance - xi) * 1e3 << " mm" << std::endl;
    record(key + "newmark_time", failure.time * 1e6, 4);
    record(key + "newmark_distance", distance * 1e3, 3);
    record(key + "time_error", (failure.time - expected_time) * 1e6, 2);
    record(key + "distance_error", (distance - xi) * 1e3, 2);
    record(key + "time_met",
           met(failure.mode == ndda::fracture::FailureMode::tension &&
               std::abs(failure.time - expected_time) < 5e-6));
    record(key + "distance_met", met(std::abs(distance - xi) < 0.012));
    check(failure.mode == ndda::fracture::FailureMode::tension,
          "the first failure is tensile");
    check(std::abs(failure.time - expected_time) < 5e-6,
          "first failure within 5 us of d'Alembert's");
    check(std::abs(distance - xi) < 0.012,
          "first failure within 12 mm (two cells) of d'Alembert's place");
    check(simulator.get_n_cracked_edges() == 0 &&
            simulator.get_mesh().n_blocks() == 1,
          "detection only: nothing is split");
  }

  {
    std::string text = read_example("bar_spalling");
    text += "subsection Output\n  set Interval = 0\nend\n";
    const auto         parameters = read_parameters(text, "bar_spalling");
    ndda::Simulator<2> simulator(parameters);
    simulator.keep_measure_histories(); // the whole history
    simulator.setup();
    while (simulator.get_time() < 4e-4 - 1e-12)
      simulator.do_time_step();
    const auto  &failure  = simulator.get_first_edge_failure();
    const auto  &piece    = simulator.get_measure_histories()[2]; // 0.97 m
    double       velocity = 0, stress = 0, peak = 0;
    unsigned int n = 0;
    for (const auto &sample : piece)
      {
        if (sample.time > failure.time)
          peak = std::max(peak, std::abs(sample.stress[0][0]));
        if (sample.time > 3.8e-4)
          {
            velocity += sample.velocity[0];
            stress = std::max(stress, std::abs(sample.stress[0][0]));
            ++n;
          }
      }
    velocity /= n;
    std::cout << "DDA, splitting: first failure at " << failure.time * 1e6
              << " us, " << (L - failure.location[0]) * 1e3
              << " mm from the free end; " << simulator.get_n_cracked_edges()
              << " edges cracked, " << simulator.get_mesh().n_blocks()
              << " blocks; the piece at 0.97 m: mean velocity " << velocity
              << " m/s and largest |stress_xx| " << stress / 1e6
              << " MPa over 380-400 us (largest after the "
              << "crack " << peak / 1e6 << " MPa)" << std::endl;
    // The blocks: their cells and x-extent.
    const auto               &mesh = simulator.get_mesh().get_block_mesh();
    std::vector<unsigned int> cells(simulator.get_mesh().n_blocks(), 0);
    std::vector<double> x_min(cells.size(), 1e9), x_max(cells.size(), -1e9);
    for (unsigned int c = 0; c < mesh.triangles.size(); ++c)
      {
        const unsigned int b = mesh.cell_block[c];
        ++cells[b];
        for (const unsigned int v : mesh.triangles[c])
          {
            x_min[b] = std::min(x_min[b], mesh.vertices[v][0]);
            x_max[b] = std::max(x_max[b], mesh.vertices[v][0]);
          }
      }
    unsigned int       n_large = 0;
    std::ostringstream pieces;
    for (unsigned int b = 0; b < cells.size(); ++b)
      {
        std::cout << "  block " << b << ": " << cells[b] << " cells, x from "
                  << x_min[b] << " to " << x_max[b] << " m" << std::endl;
        n_large += cells[b] > 20 ? 1 : 0;
        pieces << (b > 0 ? ", " : "") << cells[b];
      }
    record(key + "dda_time", failure.time * 1e6, 4);
    record(key + "dda_distance", (L - failure.location[0]) * 1e3, 2);
    record(key + "cracked", simulator.get_n_cracked_edges());
    record(key + "pieces", pieces.str());
    record(key + "pieces_met", met(n_large == 2));
    record(key + "velocity", velocity, 3);
    record(key + "velocity_met", met(velocity > 0.5));
    record(key + "stress", stress / 1e6, 2);
    record(key + "peak", peak / 1e6, 3);
    record(key + "stress_met", met(stress < 0.2 * T));
    check(n_large == 2, "the bar splits into two large pieces");
    check(velocity > 0.5, "the piece leaves with a positive velocity");
    check(stress < 0.2 * T, "the piece's stress rings down below 0.2 T");
  }
  std::cout << "OK" << std::endl;
}
