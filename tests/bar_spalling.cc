// SPDX-License-Identifier: GPL-3.0-or-later
//
// Spalling in the thesis's bar (fracture issue, "must show"; thesis 7.2.3,
// Table 1): prm/bar_spalling.prm, a 35 MPa sin^2 pulse of 40 us into the
// 1 m bar, tensile strength 18 MPa. The first edge failure must appear near
// the free end where the reflected tensile wave, less the incident
// compression still arriving, first exceeds the strength.
//
// Reference: d'Alembert's solution for the bar speed c = sqrt(E / rho)
// (plane stress), with xi the distance from the free end and tau the time
// since the pulse front reached it,
//     sigma(xi, tau) = p(tau - xi / c) - p(tau + xi / c),
// searched for the earliest tau at which some xi reaches 18 MPa.
//
// Measured: the time and the distance from the free end of the earliest
// failing edge (the fracture check of each step interpolates the failure
// time within the step). At this stage ndda detects failing edges; it does
// not split them yet.

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

  std::string text = read_example("bar_spalling");
  text += "subsection Control\n  set End time = 2.7e-4\nend\n"
          "subsection Output\n  set Interval = 0\nend\n";
  const auto         parameters = read_parameters(text, "bar_spalling");
  ndda::Simulator<2> simulator(parameters);
  simulator.setup();
  while (simulator.get_time() < 2.7e-4 - 1e-12)
    simulator.do_time_step();
  const auto &failure = simulator.get_first_edge_failure();
  check(failure.mode != ndda::fracture::FailureMode::none,
        "an edge fails before 270 us");
  const double distance = L - failure.location[0];
  std::cout << "ndda: first failure at " << failure.time * 1e6 << " us, "
            << distance * 1e3 << " mm from the free end ("
            << (failure.mode == ndda::fracture::FailureMode::tension ?
                  "tension" :
                  "shear")
            << "); errors " << (failure.time - expected_time) * 1e6 << " us, "
            << (distance - xi) * 1e3 << " mm" << std::endl;
  check(failure.mode == ndda::fracture::FailureMode::tension,
        "the first failure is tensile");
  check(std::abs(failure.time - expected_time) < 5e-6,
        "first failure within 5 us of d'Alembert's");
  check(std::abs(distance - xi) < 0.012,
        "first failure within 12 mm (two cells) of d'Alembert's place");
  std::cout << "OK" << std::endl;
}
