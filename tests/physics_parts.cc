// SPDX-License-Identifier: GPL-3.0-or-later
//
// The parts of physics/ and contact/'s OpenCloseSolver without a simulator,
// on a unit square of two P1 (and then P2) triangles:
//
//  - the constitutive law registry: "linear elasticity" by default, and a
//    law this program registers ("scaled elasticity", with a parameter of
//    its own), both selected by Materials/Constitutive law in a .prm text;
//  - StressField: a uniaxial stretch gives sigma = C eps (plane stress);
//    the strain energy is eps : C : eps / 2 times the area; the internal
//    force is self-equilibrated and does the work 2 W on the stretch; an
//    infinitesimal rotation by theta leaves the strain zero and turns an
//    initial stress by theta (sigma <- R sigma R^T); the user's law doubles
//    the stress of the stretch;
//  - rotation::step_strain(): the stretch and the rotation of
//    F = (I + E) R(theta) to round-off, for turns of 1e-9 to 2.5 rad;
//  - LinearSystem and OpenCloseSolver (no contacts: one solve): for the
//    step matrix K + M / dt^2 and the right-hand side M t / dt^2 of a rigid
//    translation t, the solve gives t back (K t = 0), and the mass solve
//    M a = M g gives a = g;
//  - LinearSolver's GMRES with an earlier factorization (UMFPACK and KLU):
//    on a matrix that differs from the factorized one by a change of rank
//    3 and of rank 8 (past the fifth iteration's orthogonality check), the
//    same iterations as deal.II's SolverGMRES with right preconditioning,
//    the same solution to 1e-10 and a residual within 1e-12; a change of
//    every row that would take more iterations than it may is refused (0).

#include <deal.II/grid/grid_generator.h>

#include <deal.II/lac/solver_gmres.h>

#include <ndda/contact/open_close_solver.h>
#include <ndda/physics/constitutive_law.h>
#include <ndda/physics/finite_element.h>
#include <ndda/physics/linear_solver.h>
#include <ndda/physics/linear_system.h>
#include <ndda/physics/rotation.h>
#include <ndda/physics/stress_field.h>

#include <functional>

#include "tests.h"

using namespace dealii;
using namespace ndda;
using ndda_tests::check;

/** Linear elasticity times a factor: a law defined by this program. */
class ScaledElasticity : public ConstitutiveLaw
{
public:
  static void
  declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Factor",
                      "1",
                      Patterns::Double(0.),
                      "The stiffness over that of linear elasticity.");
  }

  void
  parse_parameters(ParameterHandler &prm) override
  {
    factor = prm.get_double("Factor");
  }

  SymmetricTensor<4, 2>
  tangent(const parameters::Material &m, const bool plane_strain) const override
  {
    return factor * isotropic_elasticity_tensor(m.youngs_modulus,
                                                m.poissons_ratio,
                                                plane_strain);
  }

private:
  double factor = 1;
};

NDDA_REGISTER_PLUGIN(ConstitutiveLaw,
                     ScaledElasticity,
                     "scaled elasticity",
                     "Linear elasticity times Factor (a test law).")

/**
 * A law whose tangent depends on the stress: linear elasticity, times Ratio
 * wherever sigma_xx exceeds Threshold (a test law).
 */
class StressSoftening : public ConstitutiveLaw
{
public:
  static void
  declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Threshold", "1e6", Patterns::Double(), "Pa");
    prm.declare_entry("Ratio", "0.25", Patterns::Double(0.), "");
  }

  void
  parse_parameters(ParameterHandler &prm) override
  {
    threshold = prm.get_double("Threshold");
    ratio     = prm.get_double("Ratio");
  }

  SymmetricTensor<4, 2>
  tangent(const parameters::Material &m, const bool plane_strain) const override
  {
    return isotropic_elasticity_tensor(m.youngs_modulus,
                                       m.poissons_ratio,
                                       plane_strain);
  }

  bool
  tangent_depends_on_stress() const override
  {
    return true;
  }

  SymmetricTensor<4, 2>
  point_tangent(const parameters::Material  &m,
                const bool                   plane_strain,
                const SymmetricTensor<2, 2> &stress) const override
  {
    return (stress[0][0] > threshold ? ratio : 1.) * tangent(m, plane_strain);
  }

private:
  double threshold = 1e6, ratio = 0.25;
};

NDDA_REGISTER_PLUGIN(ConstitutiveLaw,
                     StressSoftening,
                     "stress softening",
                     "Elasticity softened by Ratio above a stress (a test "
                     "law).")

namespace
{
  const double E = 10e9, nu = 0.25, thickness = 0.5;

  /** subsection Materials with one material 'rock' and @p law_lines. */
  parameters::Materials
  read_materials(const std::string &law_lines)
  {
    ParameterHandler               prm;
    const std::vector<std::string> names = {"rock"};
    parameters::Materials::declare_parameters(prm, names);
    prm.parse_input_from_string("subsection Materials\n"
                                "  set Names = rock\n"
                                "  set Thickness = 0.5\n" +
                                law_lines +
                                "  subsection rock\n"
                                "    set Density = 2000\n"
                                "    set Young's modulus = 10e9\n"
                                "    set Poisson's ratio = 0.25\n"
                                "  end\n"
                                "end\n");
    parameters::Materials materials;
    materials.parse_parameters(prm, names);
    return materials;
  }

  /** The unit square as two triangles, with its space and its parts. */
  struct Square
  {
    Square(const std::string &element_name, const parameters::Materials &m)
      : materials(m)
      , mapping(linear_mapping())
    {
      Triangulation<2> triangulation;
      GridGenerator::subdivided_hyper_rectangle_with_simplices(triangulation,
                                                               {1, 1},
                                                               Point<2>(0, 0),
                                                               Point<2>(1, 1));
      mesh.build(triangulation);
      element = std::make_unique<Element>(make_element(element_name));
      dof_handler.reinit(mesh.get_triangulation());
      dof_handler.distribute_dofs(*element->system);
      dof_map.reinit(dof_handler);
      cache.set_quadratures(element->cell_quadrature, element->mass_quadrature);
      cache.update(dof_handler, dof_map, mapping, materials, false, 0.);
      cell_material.assign(mesh.get_triangulation().n_active_cells(), 0);
      stresses.initialize(
        cache, dof_map, materials, cell_material, mesh.get_triangulation());
      stresses.reinit(cell_material.size(), cache.n_quadrature_points());
      const NodeLocator nodes(mesh, dof_handler, dof_map);
      support_points = nodes.support_points;
      component      = nodes.component;
      constraints.setup(parameters::BoundaryConditions(),
                        parameters::ConstraintMethod::exact,
                        nodes);
    }

    ~Square()
    {
      dof_handler.clear();
    }

    /** The dof vector of the displacement field u(x). */
    Vector<double>
    interpolate(const std::function<Tensor<1, 2>(const Point<2> &)> &u) const
    {
      Vector<double> d(dof_handler.n_dofs());
      for (unsigned int i = 0; i < d.size(); ++i)
        d[i] = u(support_points[i])[component[i]];
      return d;
    }

    parameters::Materials     materials;
    LinearMapping             mapping;
    CrackableMesh             mesh;
    std::unique_ptr<Element>  element;
    DoFHandler<2>             dof_handler;
    DofMap                    dof_map;
    ElementCache<2>           cache;
    std::vector<unsigned int> cell_material;
    StressField               stresses;
    std::vector<Point<2>>     support_points;
    std::vector<unsigned int> component;
    Constraints               constraints;
  };

  /** The stretch u = (eps x, 0), its stresses, energy and force. */
  void
  check_stretch(const std::string &element_name,
                const std::string &law_lines,
                const double       factor)
  {
    Square       square(element_name, read_materials(law_lines));
    const double eps = 1e-4;
    const auto   d   = square.interpolate([&](const Point<2> &x) {
      return Tensor<1, 2>({eps * x[0], 0.});
    });
    square.stresses.advance(d);
    const double expected_xx = factor * E / (1 - nu * nu) * eps;
    for (unsigned int c = 0; c < square.stresses.n_cells(); ++c)
      for (const auto &sigma : square.stresses[c])
        {
          check(std::abs(sigma[0][0] - expected_xx) < 1e-9 * expected_xx,
                "sigma_xx of the stretch");
          check(std::abs(sigma[1][1] - nu * expected_xx) < 1e-9 * expected_xx,
                "sigma_yy of the stretch");
          check(std::abs(sigma[0][1]) < 1e-9 * expected_xx,
                "sigma_xy of the stretch");
        }
    Vector<double> force(square.dof_handler.n_dofs());
    const double   energy   = square.stresses.internal_force(force);
    const double   expected = 0.5 * expected_xx * eps * thickness;
    double         net_x = 0, net_y = 0;
    for (unsigned int i = 0; i < force.size(); ++i)
      (square.component[i] == 0 ? net_x : net_y) += force[i];
    check(std::abs(energy - expected) < 1e-9 * expected, "strain energy");
    check(std::abs(net_x) + std::abs(net_y) < 1e-9 * force.linfty_norm(),
          "internal force self-equilibrated");
    check(std::abs(force * d - 2 * energy) < 1e-9 * energy,
          "work of the internal force");
    std::cout << element_name << ", " << square.materials.constitutive_law_name
              << ": sigma_xx = " << square.stresses.mean(0)[0][0]
              << " Pa, strain energy = " << energy << " J" << std::endl;
  }

  /**
   * The element stiffness of a law whose tangent depends on the stress:
   * d^T K d of a stretch is t A eps C_xxxx(sigma) eps with the tangent at
   * each point's stress, and every cell is rebuilt though none moved.
   */
  void
  check_point_tangents(const std::string &element_name)
  {
    Square       square(element_name,
                  read_materials("  set Constitutive law = stress softening\n"
                                       "  subsection stress softening\n"
                                       "    set Threshold = 1e6\n"
                                       "    set Ratio = 0.25\n"
                                       "  end\n"));
    const double eps            = 1e-4;
    const auto   d              = square.interpolate([&](const Point<2> &x) {
      return Tensor<1, 2>({eps * x[0], 0.});
    });
    const auto   stretch_energy = [&]() {
      double             dKd = 0;
      const unsigned int n   = square.dof_map.dofs_per_cell;
      for (unsigned int c = 0; c < square.stresses.n_cells(); ++c)
        {
          const auto *cell_dofs = square.dof_map.dofs_of_cell(c);
          for (unsigned int i = 0; i < n; ++i)
            for (unsigned int j = 0; j < n; ++j)
              dKd += d[cell_dofs[i]] * square.cache[c].stiffness(i, j) *
                     d[cell_dofs[j]];
        }
      return dKd;
    };
    const double elastic = thickness * eps * eps * E / (1 - nu * nu);
    for (const double sigma_xx : {2e6, 0.})
      {
        for (unsigned int c = 0; c < square.stresses.n_cells(); ++c)
          for (auto &sigma : square.stresses[c])
            sigma[0][0] = sigma_xx;
        const unsigned int n_computed =
          square.cache.update(square.dof_handler,
                              square.dof_map,
                              square.mapping,
                              square.materials,
                              true,
                              1e9,
                              &square.stresses.values());
        check(n_computed == square.stresses.n_cells(),
              "every cell rebuilt with a stress-dependent tangent");
        const double expected = (sigma_xx > 1e6 ? 0.25 : 1.) * elastic;
        check(std::abs(stretch_energy() - expected) < 1e-9 * expected,
              "d^T K d with the tangent at the stress");
        std::cout << element_name
                  << ", stress softening at sigma_xx = " << sigma_xx
                  << " Pa: d^T K d = " << stretch_energy() << " J (elastic "
                  << elastic << " J)" << std::endl;
      }
    // A law whose tangent does not depend on the stress rebuilds only the
    // cells that moved: none.
    Square unmoved(element_name, read_materials(""));
    check(unmoved.cache.update(unmoved.dof_handler,
                               unmoved.dof_map,
                               unmoved.mapping,
                               unmoved.materials,
                               true,
                               1e9,
                               &unmoved.stresses.values()) == 0,
          "no cell rebuilt with a constant tangent");
  }

  /**
   * A finite rigid rotation by 0.5 rad of a prestressed square: the
   * stresses turn exactly (R sigma R^T) and take no strain, and on the
   * turned geometry the internal force is the old one turned, though the
   * element data are those of the start geometry.
   */
  void
  check_rotation(const std::string &element_name)
  {
    Square       square(element_name, read_materials(""));
    const double theta = 0.5, s0 = 1e6;
    for (unsigned int c = 0; c < square.stresses.n_cells(); ++c)
      for (auto &sigma : square.stresses[c])
        sigma[0][0] = s0;
    Vector<double> force0(square.dof_handler.n_dofs());
    const double   energy0 = square.stresses.internal_force(force0);
    const double   c = std::cos(theta), s = std::sin(theta);
    const auto     d = square.interpolate([&](const Point<2> &x) {
      return Tensor<1, 2>(
        {(c - 1) * x[0] - s * x[1], s * x[0] + (c - 1) * x[1]});
    });
    square.stresses.advance(d);
    for (unsigned int cell = 0; cell < square.stresses.n_cells(); ++cell)
      for (const auto &sigma : square.stresses[cell])
        {
          check(std::abs(sigma[0][0] - c * c * s0) < 1e-9 * s0,
                "rotated sigma_xx");
          check(std::abs(sigma[1][1] - s * s * s0) < 1e-9 * s0,
                "rotated sigma_yy");
          check(std::abs(sigma[0][1] - c * s * s0) < 1e-9 * s0,
                "rotated sigma_xy");
        }
    square.mesh.move_vertices(square.dof_map.vertex_values(d));
    Vector<double> force(square.dof_handler.n_dofs());
    const double   energy = square.stresses.internal_force(force);
    double         error  = 0;
    for (const auto &dofs : square.dof_map.node_dofs)
      {
        const double x = force0[dofs[0]], y = force0[dofs[1]];
        error = std::max({error,
                          std::abs(force[dofs[0]] - (c * x - s * y)),
                          std::abs(force[dofs[1]] - (s * x + c * y))});
      }
    check(error < 1e-9 * force0.linfty_norm(), "internal force turned");
    check(std::abs(energy - energy0) < 1e-9 * energy0,
          "strain energy kept by a rotation");
    std::cout << element_name << ": rotation by " << theta
              << " rad, sigma_xy = " << square.stresses.mean(0)[0][1]
              << " Pa, internal force turned, strain energy " << energy
              << " J (before " << energy0 << " J)" << std::endl;
  }

  /**
   * StressField::advance_with_internal_force() gives, to the bit, what
   * advance(), moving the vertices and internal_force() give: the same
   * stresses, force and energy (the step's one pass over the cells), for
   * a motion that turns, stretches and (P2) bends the cells.
   */
  void
  check_fused_pass(const std::string &element_name)
  {
    Square apart(element_name, read_materials(""));
    Square fused(element_name, read_materials(""));
    for (Square *square : {&apart, &fused})
      for (unsigned int c = 0; c < square->stresses.n_cells(); ++c)
        for (auto &sigma : square->stresses[c])
          {
            sigma[0][0] = 1e6 * (c + 1);
            sigma[1][1] = -3e5;
            sigma[0][1] = 2e5 * c;
          }
    const auto motion = [](const Point<2> &x) {
      return Tensor<1, 2>({0.1 * x[0] - 0.3 * x[1] + 0.05 * x[1] * x[1],
                           0.2 * x[0] + 0.02 * x[1] - 0.04 * x[0] * x[1]});
    };
    const Vector<double> d = apart.interpolate(motion);
    apart.stresses.advance(d);
    apart.mesh.move_vertices(apart.dof_map.vertex_values(d));
    Vector<double> force_apart(apart.dof_handler.n_dofs());
    const double   energy_apart = apart.stresses.internal_force(force_apart);

    const std::vector<Point<2>> start = fused.mesh.get_block_mesh().vertices;
    Vector<double>              force_fused(fused.dof_handler.n_dofs());
    const double                energy_fused =
      fused.stresses.advance_with_internal_force(fused.interpolate(motion),
                                                 force_fused);
    check(fused.mesh.get_block_mesh().vertices == start,
          "the one pass leaves the vertices where they were");
    check(apart.stresses.values() == fused.stresses.values(),
          "the one pass: the same stresses to the bit");
    bool same_force = force_apart.size() == force_fused.size();
    for (unsigned int i = 0; same_force && i < force_apart.size(); ++i)
      same_force = force_apart[i] == force_fused[i];
    check(same_force, "the one pass: the same internal force to the bit");
    check(energy_apart == energy_fused,
          "the one pass: the same strain energy to the bit");
    check(force_apart.linfty_norm() > 0. && energy_apart > 0.,
          "the one pass: a force and an energy to compare");
    std::cout << element_name
              << ": stress update and internal force in one pass, the same "
                 "to the bit (energy "
              << energy_fused << " J)" << std::endl;
  }

  /**
   * rotation::step_strain() without trigonometric functions: for
   * F = (I + E) R(theta), E symmetric, the strain is E and the rotation's
   * cos - 1 and sin are those of theta, to round-off, for turns from
   * 1e-9 rad (where cos - 1 computed as cos(theta) - 1 would be 0) to
   * 2.5 rad (a < 0).
   */
  void
  check_step_strain()
  {
    SymmetricTensor<2, 2> E;
    E[0][0] = 2e-4;
    E[1][1] = -1e-4;
    E[0][1] = 5e-5;
    for (const double theta : {0., 1e-9, 1e-4, 0.3, 2.5, -1.})
      {
        const double half          = std::sin(0.5 * theta);
        const double cos_minus_one = -2. * half * half, sin = std::sin(theta);
        // G = F - I = E R + (R - I), without the cancellation of F - I.
        Tensor<2, 2> G = E * rotation::matrix(cos_minus_one, sin);
        G[0][0] += cos_minus_one;
        G[1][1] += cos_minus_one;
        G[0][1] -= sin;
        G[1][0] += sin;
        const rotation::StepStrain step = rotation::step_strain(G);
        const std::string at = " at theta = " + Utilities::to_string(theta);
        // G's skew part carries the round-off of E's entries: ~1e-16 |E|
        // in sin, ~1e-16 |E| |sin| in cos - 1.
        check(std::abs(step.sin - sin) <=
                  1e-14 * std::abs(sin) + 1e-15 * E.norm() &&
                std::abs(step.cos_minus_one - cos_minus_one) <=
                  1e-14 * std::abs(cos_minus_one) +
                    1e-15 * E.norm() * std::abs(sin),
              "step_strain: the rotation" + at);
        check((step.strain - E).norm() <= 1e-12 * E.norm(),
              "step_strain: the stretch" + at);
      }
    std::cout << "step_strain: stretch and rotation of F = (I + E) R, theta "
                 "from 1e-9 to 2.5 rad"
              << std::endl;
  }

  /** A rigid translation through LinearSystem and OpenCloseSolver. */
  void
  check_solves(const std::string &element_name)
  {
    Square       square(element_name, read_materials(""));
    BoltSprings  no_bolts;
    LinearSystem system;
    system.initialize(parameters::LinearSolverType::umfpack, 1e-12);
    DynamicSparsityPattern dsp(square.dof_handler.n_dofs());
    DoFTools::make_sparsity_pattern(square.dof_handler, dsp);
    system.reinit(dsp, square.constraints, false);
    const Vector<double> zero(square.dof_handler.n_dofs());
    system.assemble(square.cache, square.dof_map, no_bolts, zero);
    const double dt = 1e-3;
    system.prepare_step(dt, 1. / (dt * dt), 1. / dt, square.constraints, 0.);

    const auto     t = square.interpolate([](const Point<2> &) {
      return Tensor<1, 2>({0.3, -0.2});
    });
    Vector<double> rhs(t.size());
    system.get_mass_matrix().vmult(rhs, t);
    rhs /= dt * dt;
    contact::OpenCloseSolver solver;
    Vector<double>           d, correction;
    check(solver.solve(system,
                       nullptr,
                       rhs,
                       Vector<double>(t.size()),
                       square.constraints,
                       d,
                       correction),
          "a solve without contacts settles");
    d -= t;
    check(d.linfty_norm() < 1e-9 * t.linfty_norm(), "rigid translation");
    check(correction.linfty_norm() == 0., "no inertia correction");

    Vector<double> force(t.size()), a;
    system.get_mass_matrix().vmult(force, t);
    system.solve_mass(force, square.constraints, a);
    a -= t;
    check(a.linfty_norm() < 1e-9 * t.linfty_norm(), "mass solve");
    std::cout << element_name << ": rigid translation and mass solve exact, "
              << system.n_factorizations() << " factorization" << std::endl;
  }

  /** A factorization as deal.II preconditioner. */
  struct Factorization
  {
    LinearSolver *solver;

    void
    vmult(Vector<double> &dst, const Vector<double> &src) const
    {
      solver->solve(dst, src);
    }
  };

  void
  check_reused_factorization(const parameters::LinearSolverType type,
                             const std::string                 &name)
  {
    // A banded non-symmetric matrix with a few far couplings.
    const unsigned int     n = 60;
    DynamicSparsityPattern dsp(n);
    for (unsigned int i = 0; i < n; ++i)
      {
        for (unsigned int j = (i < 2 ? 0 : i - 2); j < std::min(n, i + 3); ++j)
          dsp.add(i, j);
        dsp.add(i, (7 * i) % n);
      }
    SparsityPattern pattern;
    pattern.copy_from(dsp);
    SparseMatrix<double> a0(pattern), a1(pattern);
    for (unsigned int i = 0; i < n; ++i)
      {
        a0.add(i, (7 * i) % n, 0.3);
        for (unsigned int j = (i < 2 ? 0 : i - 2); j < std::min(n, i + 3); ++j)
          a0.add(i, j, i == j ? 6. + 0.01 * i : (j < i ? -1. : -0.7));
      }
    LinearSolver solver(type, 1e-12);
    solver.factorize(a0);
    Vector<double> b(n);
    for (unsigned int i = 0; i < n; ++i)
      b[i] = std::sin(i + 1.);

    std::cout << name << ": GMRES with an earlier factorization,";
    for (const unsigned int rank : {3u, 8u, n})
      {
        a1.copy_from(a0);
        for (unsigned int r = 0; r < rank; ++r)
          {
            const unsigned int row = (r * 37 + 5) % n;
            a1.add(row, row, 2. + r);
            a1.add(row, (7 * row) % n, 0.5);
          }
        // Up to 20 iterations; for the change of every row, as many as a
        // factorization costs (a few).
        const unsigned int min_iterations = rank == n ? 2 : 20;
        Vector<double>     x;
        const unsigned int iterations = solver.solve_with_earlier_factorization(
          a1, x, b, min_iterations, 1e-12);
        if (rank == n)
          {
            check(iterations == 0, name + ": a change of every row refused");
            std::cout << " a change of every row refused" << std::endl;
            continue;
          }
        const unsigned int          limit = solver.reuse_limit(min_iterations);
        SolverControl               control(limit, 1e-12 * b.l2_norm());
        SolverGMRES<Vector<double>> gmres(
          control,
          SolverGMRES<Vector<double>>::AdditionalData(limit + 2, true));
        Vector<double> y(n);
        gmres.solve(a1, y, b, Factorization{&solver});
        // Flexible GMRES with the factorization searches the Krylov space
        // of SolverGMRES with right preconditioning.
        check(iterations == control.last_step(),
              name + ": GMRES takes SolverGMRES's iterations");
        Vector<double> difference(y);
        difference -= x;
        check(difference.l2_norm() <= 1e-10 * y.l2_norm(),
              name + ": GMRES gives SolverGMRES's solution");
        Vector<double> residual(n);
        a1.vmult(residual, x);
        residual -= b;
        check(residual.l2_norm() <= 1e-12 * b.l2_norm(),
              name + ": GMRES converged");
        std::cout << " rank " << rank << " change: " << iterations
                  << " solves with the factors, SolverGMRES "
                  << control.last_step() << ", the same solution;";
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const auto                       names = ConstitutiveLawRegistry::names();
  check(std::find(names.begin(), names.end(), "linear elasticity") !=
            names.end() &&
          std::find(names.begin(), names.end(), "scaled elasticity") !=
            names.end() &&
          std::find(names.begin(), names.end(), "stress softening") !=
            names.end(),
        "the laws registered");
  check_step_strain();
  for (const std::string element : {"FE_SimplexP(1)", "FE_SimplexP(2)"})
    {
      check_stretch(element, "", 1.);
      check_stretch(element,
                    "  set Constitutive law = scaled elasticity\n"
                    "  subsection scaled elasticity\n"
                    "    set Factor = 2\n"
                    "  end\n",
                    2.);
      check_rotation(element);
      check_fused_pass(element);
      check_point_tangents(element);
      check_solves(element);
    }
  check_reused_factorization(parameters::LinearSolverType::umfpack, "UMFPACK");
  check_reused_factorization(parameters::LinearSolverType::klu, "KLU");
  return 0;
}
