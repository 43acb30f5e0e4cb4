// SPDX-License-Identifier: GPL-3.0-or-later
//
// Patch test: a linear displacement field prescribed on the boundary of an
// unstructured mesh must be reproduced exactly inside, and the stress must
// be the same constant C : eps in every cell, for P1 and P2, and for
// FE_SimplexP_Bubbles(2) (P2 with a cubic bubble), chosen by name: an
// element for which ndda has no code of its own.

#include <array>
#include <vector>

#include "tests.h"

using namespace ndda_tests;

const std::string scene = R"(
subsection Control
  set Analysis type = quasi-static
  set Time step = 1
  set End time = 1
  set {element}
  set Maximum displacement ratio = 1
end
subsection Materials
  set Names = rock
  set Plane condition = {plane}
  subsection rock
    set Young's modulus = 30e9
    set Poisson's ratio = 0.3
  end
end
subsection Geometry
  set Blocks = patch
  subsection patch
    set Outer boundary = 0, 0; 1, 0; 1.2, 0.9; 0.1, 1.1
    set Material = rock
    set Mesh size = 0.25
  end
end
subsection Boundary conditions
  set Names = linear
  subsection linear
    set Type = displacement
    set Segments = 0, 0, 1, 0; 1, 0, 1.2, 0.9; 1.2, 0.9, 0.1, 1.1; 0.1, 1.1, 0, 0
    set Value = 1e-3 + 1e-3*x + 2e-3*y; -2e-3 - 0.5e-3*x + 3e-3*y
  end
end
)";

int
main(int argc, char **argv)
{
  using namespace dealii;
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  // The entry that chooses the element, its name in the output and in the
  // keys of doc/validation.md.
  const std::vector<std::array<std::string, 3>> elements = {
    {{"Element degree = 1", "P1", "p1"}},
    {{"Element degree = 2", "P2", "p2"}},
    {{"Finite element = FE_SimplexP_Bubbles(2)",
      "FE_SimplexP_Bubbles(2)",
      "p2_bubbles"}}};
  for (const std::string plane : {"plane stress", "plane strain"})
    for (const auto &[entry, element, element_key] : elements)
      {
        auto parameters =
          read_parameters(substitute(scene,
                                     {{"element", entry}, {"plane", plane}}),
                          "patch_test");
        ndda::Simulator<2> simulator(parameters);
        simulator.setup();
        // Initial positions of the nodes, before the mesh moves.
        std::vector<Point<2>> support(simulator.get_dof_handler().n_dofs());
        DoFTools::map_dofs_to_support_points(simulator.get_mapping(),
                                             simulator.get_dof_handler(),
                                             support);
        simulator.do_time_step();

        // Exact fields.
        const double eps_xx = 1e-3, eps_yy = 3e-3,
                     eps_xy     = 0.5 * (2e-3 - 0.5e-3);
        double      max_u_error = 0, max_u = 0;
        const auto &fe = simulator.get_dof_handler().get_fe();
        std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
        for (const auto &cell :
             simulator.get_dof_handler().active_cell_iterators())
          {
            cell->get_dof_indices(dofs);
            for (unsigned int i = 0; i < dofs.size(); ++i)
              {
                const Point<2> &x = support[dofs[i]];
                const double    exact =
                  fe.system_to_component_index(i).first == 0 ?
                       1e-3 + 1e-3 * x[0] + 2e-3 * x[1] :
                       -2e-3 - 0.5e-3 * x[0] + 3e-3 * x[1];
                max_u_error =
                  std::max(max_u_error,
                           std::abs(simulator.get_displacement()[dofs[i]] -
                                    exact));
                max_u = std::max(max_u, std::abs(exact));
              }
          }
        const double E = 30e9, nu = 0.3;
        const double lambda = plane == "plane strain" ?
                                E * nu / ((1 + nu) * (1 - 2 * nu)) :
                                E * nu / (1 - nu * nu);
        const double mu     = E / (2 * (1 + nu));
        // The strain of ndda's kinematics is the stretch of the polar
        // decomposition F = V R, V - I (doc/theory.md, "Finite rotation");
        // V = sqrt(F F^T) here from the eigenvectors of F F^T. It differs
        // from the linear strain eps by terms of order |grad u|^2.
        Tensor<2, 2> F;
        F[0][0] = 1 + eps_xx;
        F[0][1] = 2e-3;
        F[1][0] = -0.5e-3;
        F[1][1] = 1 + eps_yy;
        SymmetricTensor<2, 2> strain;
        for (const auto &[value, vector] :
             eigenvectors(symmetrize(F * transpose(F))))
          strain +=
            std::sqrt(value) * symmetrize(outer_product(vector, vector));
        strain -= unit_symmetric_tensor<2>();
        SymmetricTensor<2, 2> exact_stress =
          lambda * trace(strain) * unit_symmetric_tensor<2>() + 2 * mu * strain;
        SymmetricTensor<2, 2> linear_stress;
        linear_stress[0][0]     = lambda * (eps_xx + eps_yy) + 2 * mu * eps_xx;
        linear_stress[1][1]     = lambda * (eps_xx + eps_yy) + 2 * mu * eps_yy;
        linear_stress[0][1]     = 2 * mu * eps_xy;
        double max_stress_error = 0;
        for (unsigned int c = 0;
             c < simulator.get_mesh().get_triangulation().n_active_cells();
             ++c)
          for (const auto &sigma : simulator.get_cell_stress(c))
            max_stress_error =
              std::max(max_stress_error, (sigma - exact_stress).norm());
        const double u_error      = max_u_error / max_u;
        const double stress_error = max_stress_error / exact_stress.norm();
        std::cout << plane << ", " << element << ": "
                  << simulator.get_mesh().get_triangulation().n_active_cells()
                  << " cells, relative displacement error " << std::scientific
                  << std::setprecision(2) << u_error
                  << ", relative stress error " << stress_error
                  << " (the stress of the linear strain differs by "
                  << (exact_stress - linear_stress).norm() / exact_stress.norm()
                  << ")" << std::defaultfloat << std::endl;
        const std::string key =
          "patch_test." +
          std::string(plane == "plane stress" ? "stress" : "strain") + "_" +
          element_key + ".";
        record(key + "u_error", u_error, 2);
        record(key + "stress_error", stress_error, 2);
        record(key + "linear_difference",
               (exact_stress - linear_stress).norm() / exact_stress.norm(),
               2);
        check(u_error < 1e-11, "displacement not reproduced to round-off");
        check(stress_error < 1e-11, "stress not reproduced to round-off");
      }
  std::cout << "OK" << std::endl;
}
