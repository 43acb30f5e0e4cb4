// SPDX-License-Identifier: GPL-3.0-or-later
//
// Mass and load kernels: total mass, gravity resultant, point load and line
// load resultants, exact to round-off, on a meshed disc (a 64-gon) and on
// an L-shaped block with a hole, for P1 and P2.

#include <cmath>
#include <sstream>

#include "tests.h"

using namespace ndda_tests;

const std::string scene = R"(
subsection Control
  set Element degree = {degree}
  set Time step = 1e-3
  set End time = 1
end
subsection Materials
  set Names = rock
  set Thickness = 0.5
  subsection rock
    set Density = 2500
  end
end
subsection Geometry
  set Blocks = disc, ell
  subsection disc
    set Outer boundary = {disc}
    set Material = rock
    set Mesh size = 0.1
  end
  subsection ell
    set Outer boundary = 2, 0; 4, 0; 4, 1; 3, 1; 3, 2; 2, 2
    set Holes = 2.3, 0.3; 2.7, 0.3; 2.7, 0.7; 2.3, 0.7
    set Material = rock
    set Mesh size = 0.15
  end
end
subsection Loads
  set Gravity = 0.5 * t; -9.81
  set Point loads = push
  set Line loads = pressure, shear
  subsection push
    set Point = 0.1, 0.2
    set Force = 300 * t; -700
  end
  subsection pressure
    # top of the L's leg, outward normal (0, 1)
    set Segment = 3, 1, 4, 1
    set Type = pressure
    set Value = 2e6 * t
  end
  subsection shear
    # left edge of the L, a traction varying along y
    set Segment = 2, 0, 2, 2
    set Type = traction
    set Value = 1e5 * y; 3e5 * (1 + y) * t
  end
end
)";

int
main(int argc, char **argv)
{
  using namespace dealii;
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  const unsigned int n_sides = 64;
  const double       radius  = 0.5;
  std::ostringstream disc;
  disc << std::setprecision(17);
  for (unsigned int i = 0; i < n_sides; ++i)
    disc << (i > 0 ? "; " : "") << radius * std::cos(2 * M_PI * i / n_sides)
         << ", " << radius * std::sin(2 * M_PI * i / n_sides);
  const double disc_area =
    0.5 * n_sides * radius * radius * std::sin(2 * M_PI / n_sides);
  const double ell_area = 2 * 1 + 1 * 1 - 0.4 * 0.4;
  const double area     = disc_area + ell_area;
  const double rho = 2500, thickness = 0.5;
  const double t = 2;

  for (const unsigned int degree : {1u, 2u})
    {
      auto parameters =
        read_parameters(substitute(scene,
                                   {{"degree", std::to_string(degree)},
                                    {"disc", disc.str()}}),
                        "mass_and_loads");
      ndda::Simulator<2> simulator(parameters);
      simulator.setup();
      simulator.do_time_step(); // builds the matrices

      const auto    &dof_handler = simulator.get_dof_handler();
      Vector<double> ex(dof_handler.n_dofs()), ey(dof_handler.n_dofs());
      const auto    &fe = dof_handler.get_fe();
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            (fe.system_to_component_index(i).first == 0 ? ex : ey)[dofs[i]] = 1;
        }
      // The mesh has moved a little in the first step; mass does not
      // change, and the loads are compared on the moved mesh's lengths,
      // which are those of the initial segments up to the motion.
      const double mass = simulator.get_mass_matrix().matrix_norm_square(ex);
      const double exact_mass = rho * thickness * area;

      // Gravity alone: switch the other loads off by comparing with their
      // exact resultants.
      Vector<double> force;
      simulator.assemble_external_force(t, force);
      const double fx = force * ex, fy = force * ey;
      const double exact_fx = rho * thickness * area * 0.5 * t + 300 * t +
                              thickness * (1e5 * 2 * 2 / 2);
      const double exact_fy = -rho * thickness * area * 9.81 - 700 -
                              thickness * 2e6 * t * 1 +
                              thickness * 3e5 * t * (2 + 2 * 2 / 2);
      const double mass_error = std::abs(mass - exact_mass) / exact_mass;
      const double fx_error   = std::abs(fx - exact_fx) / std::abs(exact_fx);
      const double fy_error   = std::abs(fy - exact_fy) / std::abs(exact_fy);
      std::cout << "P" << degree << ": "
                << simulator.get_mesh().get_triangulation().n_active_cells()
                << " cells; mass " << std::setprecision(12) << mass
                << " kg (exact " << exact_mass << "), relative error "
                << std::scientific << std::setprecision(2) << mass_error
                << "; resultant (" << std::defaultfloat << std::setprecision(12)
                << fx << ", " << fy << ") N, relative errors "
                << std::scientific << std::setprecision(2) << fx_error << ", "
                << fy_error << std::defaultfloat << std::endl;
      const std::string key = "mass_and_loads.p" + std::to_string(degree) + ".";
      record(key + "mass_error", mass_error, 2);
      record(key + "fx_error", fx_error, 2);
      record(key + "fy_error", fy_error, 2);
      check(mass_error < 1e-12, "total mass");
      check(fx_error < 1e-12 && fy_error < 1e-12, "load resultant");
    }
  std::cout << "OK" << std::endl;
}
