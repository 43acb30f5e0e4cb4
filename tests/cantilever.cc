// SPDX-License-Identifier: GPL-3.0-or-later
//
// Cantilever under an end load, plane stress: the exact solution of
// Timoshenko & Goodier (Theory of Elasticity, sec. 21). The beam occupies
// 0 <= x <= l, -c <= y <= c; the load P is a parabolic shear traction on
// x = 0, and the exact displacement is prescribed on x = l, so that the
// finite element solution converges to the exact field; the tip deflection
// is v(0, 0) = P l^3 / (3 E I). Prints the error for P1 and P2 under
// refinement and checks that it decreases at least at the expected rate.

#include <cmath>

#include "tests.h"

using namespace ndda_tests;

const std::string scene = R"(
subsection Control
  set Analysis type = quasi-static
  set Time step = 1
  set End time = 1
  set Element degree = {degree}
  set Maximum displacement ratio = 1
end
subsection Materials
  set Names = rock
  set Plane condition = plane stress
  subsection rock
    set Young's modulus = {E}
    set Poisson's ratio = {nu}
  end
end
subsection Geometry
  set Blocks = beam
  subsection beam
    set Outer boundary = 0, -{c}; {l}, -{c}; {l}, {c}; 0, {c}
    set Material = rock
    set Mesh size = {h}
  end
end
subsection Loads
  set Line loads = end_load
  subsection end_load
    set Segment = 0, -{c}, 0, {c}
    set Type = traction
    set Value = 0; {P} / (2 * {I}) * ({c}^2 - y^2)
  end
end
subsection Boundary conditions
  set Names = clamp
  subsection clamp
    set Type = displacement
    set Segments = {l}, -{c}, {l}, {c}
    set Value = -{P}*x^2*y/(2*{E}*{I}) - {nu}*{P}*y^3/(6*{E}*{I}) + {P}*y^3/(6*{I}*{G}) + ({P}*{l}^2/(2*{E}*{I}) - {P}*{c}^2/(2*{I}*{G}))*y; {nu}*{P}*x*y^2/(2*{E}*{I}) + {P}*x^3/(6*{E}*{I}) - {P}*{l}^2*x/(2*{E}*{I}) + {P}*{l}^3/(3*{E}*{I})
  end
end
subsection Output
  set Measure points = 0, 0
end
)";

int
main(int argc, char **argv)
{
  using namespace dealii;
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  const double l = 5, c = 0.5, E = 30e9, nu = 0.25, P = 1e6;
  const double I = 2 * c * c * c / 3, G = E / (2 * (1 + nu));
  const double exact = P * l * l * l / (3 * E * I);
  const auto   str   = [](const double x) {
    std::ostringstream out;
    out << std::setprecision(17) << x;
    return out.str();
  };
  std::cout << "exact tip deflection P l^3 / (3 E I) = " << exact << " m"
            << std::endl;
  for (const unsigned int degree : {1u, 2u})
    {
      std::vector<double> errors;
      for (const double h : {0.5, 0.25, 0.125, 0.0625})
        {
          auto parameters =
            read_parameters(substitute(scene,
                                       {{"degree", std::to_string(degree)},
                                        {"E", str(E)},
                                        {"nu", str(nu)},
                                        {"G", str(G)},
                                        {"I", str(I)},
                                        {"P", str(P)},
                                        {"l", str(l)},
                                        {"c", str(c)},
                                        {"h", str(h)}}),
                            "cantilever");
          ndda::Simulator<2> simulator(parameters);
          simulator.setup();
          simulator.do_time_step();
          const double tip =
            simulator.get_measure_histories()[0].back().displacement[1];
          errors.push_back(std::abs(tip - exact) / exact);
          std::cout << "P" << degree << "  h = " << std::setw(6) << h
                    << "  cells " << std::setw(5)
                    << simulator.get_mesh().get_triangulation().n_active_cells()
                    << "  tip deflection " << std::setprecision(8) << tip
                    << "  relative error " << std::scientific
                    << std::setprecision(2) << errors.back()
                    << std::defaultfloat;
          if (errors.size() > 1)
            std::cout << "  rate "
                      << std::log2(errors[errors.size() - 2] / errors.back());
          std::cout << std::endl;
          const std::string key = "cantilever.p" + std::to_string(degree) +
                                  "_" + std::to_string(errors.size() - 1) + ".";
          record(key + "cells",
                 simulator.get_mesh().get_triangulation().n_active_cells());
          record(key + "error", errors.back(), 2);
          if (errors.size() > 1)
            record(key + "rate",
                   std::log2(errors[errors.size() - 2] / errors.back()),
                   2);
        }
      // Each halving of h must reduce the error (unstructured meshes do
      // not give clean rates; require at least a factor 2 for P1, 4 for
      // P2 over the whole range per two refinements).
      bool decreasing = true;
      for (unsigned int i = 1; i < errors.size(); ++i)
        decreasing = decreasing && errors[i] < errors[i - 1];
      record("cantilever.p" + std::to_string(degree) + ".met",
             met(decreasing && errors.back() < (degree == 1 ? 5e-3 : 1e-6)));
      for (unsigned int i = 1; i < errors.size(); ++i)
        check(errors[i] < errors[i - 1], "error does not decrease");
      check(errors.back() < (degree == 1 ? 5e-3 : 1e-6),
            "finest error too large");
    }
  std::cout << "OK" << std::endl;
}
