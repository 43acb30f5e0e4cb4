// SPDX-License-Identifier: GPL-3.0-or-later
//
// Fracture building blocks (doc/fracture.md), checked against values
// computed by hand:
//
//  - normal and shear stress on edges of known orientation, against the
//    thesis's 5.22/5.23 with the angles read as doc/fracture.md explains;
//  - interior edges, cell-average and nodal-average edge stresses and the
//    nodal averaging weights on a four-triangle mesh plus a separate block;
//  - failure times of Mohr-Coulomb with tension cut-off (tension, shear of
//    either sign, shear stress changing sign, shear strength changing with
//    the normal stress, the earlier mode winning, already failed at the
//    start, never failing, on the limit) and of the maximum principal
//    stress criterion;
//  - the criterion registry: creation by name, an unknown name, a criterion
//    registered by this program, subsection Fracture read from a .prm text.
//
// Every measured value is printed; exact cases are checked to 1e-12
// relative to the stress scale of the case.

#include <deal.II/base/symmetric_tensor.h>

#include <ndda/fracture/edge_stress.h>
#include <ndda/fracture/fracture_criterion.h>
#include <ndda/fracture/maximum_principal_stress.h>
#include <ndda/fracture/mohr_coulomb.h>

#include <cmath>
#include <iostream>
#include <tuple>

#include "tests.h"

using namespace dealii;
using namespace ndda::fracture;
using ndda_tests::check;
using ndda_tests::check_value;
using ndda_tests::message_of;

/** A criterion defined by this program: never lets an edge fail. */
class NeverFails : public FractureCriterion
{
public:
  static void
  declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Note", "", Patterns::Anything(), "Unused.");
  }

  EdgeFailure
  failure_in_step(const EdgeState &,
                  const EdgeState &,
                  const Strength &) const override
  {
    return {};
  }
};

NDDA_REGISTER_FRACTURE_CRITERION(NeverFails,
                                 "Never fails",
                                 "A test criterion: no edge fails.")



namespace
{
  /** Check two tensors component by component. */
  void
  check_tensor(const std::string           &what,
               const SymmetricTensor<2, 2> &measured,
               const SymmetricTensor<2, 2> &expected,
               const double                 scale)
  {
    check_value(what + " xx", measured[0][0], expected[0][0], scale);
    check_value(what + " yy", measured[1][1], expected[1][1], scale);
    check_value(what + " xy", measured[0][1], expected[0][1], scale);
  }

  SymmetricTensor<2, 2>
  tensor(const double xx, const double yy, const double xy)
  {
    SymmetricTensor<2, 2> s;
    s[0][0] = xx;
    s[1][1] = yy;
    s[0][1] = xy;
    return s;
  }

  /** An edge state with only normal and shear stress set. */
  EdgeState
  state(const double normal_stress, const double shear_stress)
  {
    EdgeState s;
    s.normal_stress = normal_stress;
    s.shear_stress  = shear_stress;
    return s;
  }

  std::string
  mode_name(const FailureMode mode)
  {
    return mode == FailureMode::none    ? "none" :
           mode == FailureMode::tension ? "tension" :
                                          "shear";
  }

  /** Print a failure and check its mode and (if it fails) its time. */
  void
  check_failure(const std::string &what,
                const EdgeFailure &failure,
                const FailureMode  expected_mode,
                const double       expected_time = 0.)
  {
    std::cout << what << ": mode " << mode_name(failure.mode) << " (expected "
              << mode_name(expected_mode) << ")" << std::endl;
    check(failure.mode == expected_mode, what + ": mode");
    if (expected_mode != FailureMode::none)
      check_value("time", failure.time, expected_time);
  }



  void
  test_traction()
  {
    std::cout << "Normal and shear stress on edges" << std::endl;
    const double s = 1e6;

    // Uniaxial tension s along x on an edge at 45 degrees: the traction on
    // the normal n = (1, -1)/sqrt(2) is (s/sqrt(2), 0), so sigma_n = s/2
    // (tension) and tau = t.traction = s/2 with t = (1, 1)/sqrt(2).
    EdgeState e = edge_state(tensor(s, 0, 0), Point<2>(0, 0), Point<2>(1, 1));
    check_value("uniaxial x, 45 deg edge: sigma_n", e.normal_stress, s / 2, s);
    check_value("uniaxial x, 45 deg edge: tau", e.shear_stress, s / 2, s);
    // The same edge with its ends swapped: n and t both flip.
    e = edge_state(tensor(s, 0, 0), Point<2>(1, 1), Point<2>(0, 0));
    check_value("same edge reversed: sigma_n", e.normal_stress, s / 2, s);
    check_value("same edge reversed: tau", e.shear_stress, s / 2, s);
    // Uniaxial compression on the other diagonal: t = (-1, 1)/sqrt(2),
    // n = (1, 1)/sqrt(2), traction (-s/sqrt(2), 0): sigma_n = -s/2,
    // tau = +s/2.
    e = edge_state(tensor(-s, 0, 0), Point<2>(1, 0), Point<2>(0, 1));
    check_value("uniaxial -x, 135 deg edge: sigma_n",
                e.normal_stress,
                -s / 2,
                s);
    check_value("uniaxial -x, 135 deg edge: tau", e.shear_stress, s / 2, s);
    // A horizontal edge carries sigma_yy and -sigma_xy (n = (0, -1)).
    e =
      edge_state(tensor(3 * s, -2 * s, s), Point<2>(0.5, 2), Point<2>(4.5, 2));
    check_value("horizontal edge: sigma_n", e.normal_stress, -2 * s, s);
    check_value("horizontal edge: tau", e.shear_stress, -s, s);

    // A general tensor on a general edge against the thesis: 5.22 with the
    // angle of the normal gives sigma_n; 5.23 with the angle of the edge
    // (its "direction angle") gives tau; 5.22 with the angle of the edge
    // gives the stress along the edge, trace - sigma_n (the slip in 5.22).
    const SymmetricTensor<2, 2> sigma = tensor(2.5 * s, -1.25 * s, 0.75 * s);
    const Point<2>              a(0.3, -0.2), b(-0.9, 1.4);
    e                         = edge_state(sigma, a, b);
    const double theta_edge   = std::atan2(b[1] - a[1], b[0] - a[0]);
    const double theta_normal = theta_edge - M_PI / 2;
    const auto   eq_5_22      = [&](const double theta) {
      return 0.5 * (sigma[0][0] + sigma[1][1]) +
             0.5 * (sigma[0][0] - sigma[1][1]) * std::cos(2 * theta) +
             sigma[0][1] * std::sin(2 * theta);
    };
    const auto eq_5_23 = [&](const double theta) {
      return 0.5 * (sigma[0][0] - sigma[1][1]) * std::sin(2 * theta) -
             sigma[0][1] * std::cos(2 * theta);
    };
    check_value("general: sigma_n vs 5.22(normal angle)",
                e.normal_stress,
                eq_5_22(theta_normal),
                s);
    check_value("general: tau vs 5.23(edge angle)",
                e.shear_stress,
                eq_5_23(theta_edge),
                s);
    check_value("general: 5.22(edge angle) = trace - sigma_n",
                eq_5_22(theta_edge),
                trace(sigma) - e.normal_stress,
                s);
    check(std::abs(eq_5_22(theta_edge) - e.normal_stress) > 0.1 * s,
          "5.22 with the edge's angle differs from sigma_n in this case");

    // Rotating tensor and edge together changes nothing.
    const double          alpha = 0.7;
    const Tensor<2, 2>    r({{std::cos(alpha), -std::sin(alpha)},
                             {std::sin(alpha), std::cos(alpha)}});
    const Tensor<2, 2>    rotated_full = r * Tensor<2, 2>(sigma) * transpose(r);
    SymmetricTensor<2, 2> rotated      = symmetrize(rotated_full);
    const EdgeState       f            = edge_state(rotated,
                                   Point<2>(r * Tensor<1, 2>(a)),
                                   Point<2>(r * Tensor<1, 2>(b)));
    check_value("rotated by 0.7 rad: sigma_n",
                f.normal_stress,
                e.normal_stress,
                s);
    check_value("rotated by 0.7 rad: tau", f.shear_stress, e.shear_stress, s);
  }



  void
  test_edge_stresses()
  {
    std::cout << "Edge stresses on a small mesh" << std::endl;
    const double s = 1e6;
    // Block 1: the unit square with an off-centre vertex 4 = (0.3, 0.6),
    // four triangles of areas 0.3, 0.35, 0.2, 0.15. Block 2: one triangle
    // with its own vertices 5, 6, 7, two of them on top of vertices 1, 2.
    const std::vector<Point<2>> vertices = {
      {0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.3, 0.6}, {1, 0}, {2, 0}, {1, 1}};
    const std::vector<std::array<unsigned int, 3>> triangles = {
      {{0, 1, 4}}, {{1, 2, 4}}, {{2, 3, 4}}, {{3, 0, 4}}, {{5, 6, 7}}};
    const std::vector<double> areas = {0.3, 0.35, 0.2, 0.15, 0.5};
    const std::vector<SymmetricTensor<2, 2>> cell_stress = {
      tensor(1 * s, -2 * s, 0.5 * s),
      tensor(3 * s, 1 * s, -1 * s),
      tensor(-2 * s, 4 * s, 2 * s),
      tensor(0.5 * s, 0.25 * s, -0.75 * s),
      tensor(100 * s, 100 * s, 100 * s)};

    const std::vector<InteriorEdge> edges =
      find_interior_edges(triangles, vertices.size());
    // Edge (0,4): triangle 3 runs 0 -> 4, triangle 0 runs 4 -> 0; and so on.
    const std::vector<InteriorEdge> expected_edges = {{{{0, 4}}, {{3, 0}}},
                                                      {{{1, 4}}, {{0, 1}}},
                                                      {{{2, 4}}, {{1, 2}}},
                                                      {{{3, 4}}, {{2, 3}}}};
    std::cout << "  interior edges:";
    for (const auto &edge : edges)
      std::cout << " (" << edge.vertices[0] << "," << edge.vertices[1]
                << " | cells " << edge.cells[0] << "," << edge.cells[1] << ")";
    std::cout << std::endl;
    check(edges.size() == expected_edges.size(), "number of interior edges");
    for (unsigned int i = 0; i < edges.size(); ++i)
      check(edges[i].vertices == expected_edges[i].vertices &&
              edges[i].cells == expected_edges[i].cells,
            "interior edge " + std::to_string(i));

    // Nodal weights: vertex 0 sees triangles 3 and 0 (0.15, 0.3), vertex 1
    // triangles 0, 1 (0.3, 0.35), vertex 4 all four (sum 1), vertex 5 only
    // block 2's triangle.
    const auto nodal =
      nodal_stresses(triangles, cell_stress, areas, vertices.size());
    std::cout << "  weights at vertex 0: " << 0.3 / 0.45 << ", " << 0.15 / 0.45
              << "; vertex 1: " << 0.3 / 0.65 << ", " << 0.35 / 0.65
              << std::endl;
    check_tensor("nodal stress 0",
                 nodal[0],
                 (0.3 * cell_stress[0] + 0.15 * cell_stress[3]) / 0.45,
                 s);
    check_tensor("nodal stress 1",
                 nodal[1],
                 (0.3 * cell_stress[0] + 0.35 * cell_stress[1]) / 0.65,
                 s);
    check_tensor("nodal stress 4",
                 nodal[4],
                 0.3 * cell_stress[0] + 0.35 * cell_stress[1] +
                   0.2 * cell_stress[2] + 0.15 * cell_stress[3],
                 s);
    check_tensor("nodal stress 5 (other block)", nodal[5], cell_stress[4], s);

    // Both methods on edge (1,4), whose cells are 0 and 1.
    const auto                  cell_average  = edge_states(edges,
                                          vertices,
                                          triangles,
                                          cell_stress,
                                          areas,
                                          EdgeStressMethod::cell_average);
    const auto                  nodal_average = edge_states(edges,
                                           vertices,
                                           triangles,
                                           cell_stress,
                                           areas,
                                           EdgeStressMethod::nodal_average);
    const SymmetricTensor<2, 2> mean_of_cells =
      0.5 * (cell_stress[0] + cell_stress[1]);
    check_tensor("edge (1,4) cell average",
                 cell_average[1].stress,
                 mean_of_cells,
                 s);
    const SymmetricTensor<2, 2> mean_of_nodes =
      0.5 * ((0.3 * cell_stress[0] + 0.35 * cell_stress[1]) / 0.65 +
             (0.3 * cell_stress[0] + 0.35 * cell_stress[1] +
              0.2 * cell_stress[2] + 0.15 * cell_stress[3]));
    check_tensor("edge (1,4) nodal average",
                 nodal_average[1].stress,
                 mean_of_nodes,
                 s);
    // Edge 1 -> 4 has t = (-0.7, 0.6)/|.|, n = (0.6, 0.7)/|.|.
    const double       l = std::sqrt(0.85);
    const Tensor<1, 2> t({-0.7 / l, 0.6 / l}), n({0.6 / l, 0.7 / l});
    for (const auto &[name, states, sigma] :
         {std::make_tuple("cell average", cell_average, mean_of_cells),
          std::make_tuple("nodal average", nodal_average, mean_of_nodes)})
      {
        check_value(std::string("edge (1,4) ") + name + ": sigma_n",
                    states[1].normal_stress,
                    n * (sigma * n),
                    s);
        check_value(std::string("edge (1,4) ") + name + ": tau",
                    states[1].shear_stress,
                    t * (sigma * n),
                    s);
      }

    // A uniform stress: both methods give it back on every edge.
    const std::vector<SymmetricTensor<2, 2>> uniform(triangles.size(),
                                                     tensor(s, -s, 0.5 * s));
    for (const auto method :
         {EdgeStressMethod::cell_average, EdgeStressMethod::nodal_average})
      {
        double deviation = 0;
        for (const EdgeState &e :
             edge_states(edges, vertices, triangles, uniform, areas, method))
          deviation = std::max(deviation, (e.stress - uniform[0]).norm());
        check_value(std::string("uniform field, ") +
                      (method == EdgeStressMethod::cell_average ? "cell" :
                                                                  "nodal") +
                      " average: largest deviation on an edge",
                    deviation,
                    0,
                    s);
      }

    // Bad meshes.
    for (const auto &[name, bad, message] :
         {std::make_tuple("three triangles on one edge",
                          std::vector<std::array<unsigned int, 3>>{
                            {{0, 1, 2}}, {{1, 0, 3}}, {{0, 1, 4}}},
                          std::string(
                            "the edge (0, 1) belongs to 3 triangles")),
          std::make_tuple("a clockwise triangle",
                          std::vector<std::array<unsigned int, 3>>{{{0, 1, 2}},
                                                                   {{0, 1, 3}}},
                          std::string("one of them is clockwise"))})
      {
        const std::string what =
          message_of([&]() { find_interior_edges(bad, 5); });
        std::cout << "  " << name << ": "
                  << (what.empty() ? "no exception" : what) << std::endl;
        check(what.find(message) != std::string::npos, name);
      }
  }



  void
  test_mohr_coulomb()
  {
    std::cout << "Mohr-Coulomb with tension cut-off: c = 2 MPa, "
                 "tan(phi) = 0.5, T = 1 MPa"
              << std::endl;
    const double s = 1e6;
    Strength     strength;
    strength.cohesion         = 2 * s;
    strength.friction_angle   = std::atan(0.5);
    strength.tensile_strength = 1 * s;
    const MohrCoulomb mc;

    // Each case: start (sigma_n, tau) and end (sigma_n, tau) in MPa, the
    // expected mode and time.
    struct Case
    {
      const char *name;
      double      normal_start, shear_start, normal_end, shear_end;
      FailureMode mode;
      double      time;
    };
    const Case cases[] = {
      // sigma_n 0 -> 4: reaches T at (0 - 1)/(0 - 1 - 3) = 1/4. Shear
      // excess 0.5 sigma_n - 2 only touches zero at the end.
      {"tension crossing", 0, 0, 4, 0, FailureMode::tension, 0.25},
      // sigma_n = -2 (strength 3), tau 0 -> +6: 1/2.
      {"shear crossing, tau > 0", -2, 0, -2, 6, FailureMode::shear, 0.5},
      // The same with tau 0 -> -6 (the thesis's signed f never fails).
      {"shear crossing, tau < 0", -2, 0, -2, -6, FailureMode::shear, 0.5},
      // tau -2 -> +4 against 3: tau(t) = -2 + 6 t = 3 at t = 5/6
      // (interpolating |tau| from 2 to 4 would give 1/2).
      {"tau changes sign, +", -2, -2, -2, 4, FailureMode::shear, 5. / 6},
      // tau 2.5 -> -4: -tau(t) = -2.5 + 6.5 t = 3 at t = 11/13.
      {"tau changes sign, -", -2, 2.5, -2, -4, FailureMode::shear, 11. / 13},
      // tau = 2.5 while sigma_n goes -2 -> +2: the strength 2 - 0.5 sigma_n
      // falls from 3 to 1; excess -0.5 + 2 t = 0 at 1/4. Tension would come
      // at 3/4: shear wins.
      {"strength falls", -2, 2.5, 2, 2.5, FailureMode::shear, 0.25},
      // sigma_n 0 -> 4, tau 0 -> 2: tension at 1/4, shear excess -2 + 4 t
      // at 1/2: tension wins.
      {"tension first", 0, 0, 4, 2, FailureMode::tension, 0.25},
      // Beyond T at the start, even if relieved by the end: time 0.
      {"beyond T at the start", 1.5, 0, 0.5, 0, FailureMode::tension, 0},
      // Beyond the shear limit at the start (excess +1), back below at the
      // end (-1): time 0. The thesis's 5.33 would give 1/2.
      {"beyond shear limit at start", -2, 4, -2, 2, FailureMode::shear, 0},
      // Compression growing with the shear: excess -1.5 at both ends.
      {"never failing", -1, 1, -3, 2, FailureMode::none, 0},
      // On the tension limit all step long: not beyond, no failure.
      {"on the tension limit", 1, 0, 1, 0, FailureMode::none, 0},
      // sigma_n 0 -> 6 fails in tension at 1/6 (without the cut-off: below).
      {"with cut-off", 0, 0, 6, 0, FailureMode::tension, 1. / 6}};
    for (const Case &c : cases)
      check_failure(c.name,
                    mc.failure_in_step(state(c.normal_start * s,
                                             c.shear_start * s),
                                       state(c.normal_end * s, c.shear_end * s),
                                       strength),
                    c.mode,
                    c.time);

    // An unloaded edge of a material without strength does not fail.
    check_failure("unloaded, zero strength",
                  mc.failure_in_step(state(0, 0), state(0, 0), Strength()),
                  FailureMode::none);

    // Tie (phi = 0 for exact arithmetic): tension at (0 - 1)/(0 - 4) and
    // shear (tau 1.5 -> 2.5 against c = 1.75) at 0.25/1 both at 1/4.
    Strength tie       = strength;
    tie.friction_angle = 0;
    tie.cohesion       = 1.75 * s;
    check_failure("tie, tension wins",
                  mc.failure_in_step(state(0, 1.5 * s),
                                     state(4 * s, 2.5 * s),
                                     tie),
                  FailureMode::tension,
                  0.25);

    // Without the cut-off, sigma_n 0 -> 6 MPa fails in shear where
    // 0.5 sigma_n = 2 MPa, at 2/3.
    check_failure("no cut-off",
                  MohrCoulomb(false).failure_in_step(state(0, 0),
                                                     state(6 * s, 0),
                                                     strength),
                  FailureMode::shear,
                  2. / 3.);
  }



  void
  test_maximum_principal_stress()
  {
    std::cout << "Maximum principal stress, T = 0.5 MPa" << std::endl;
    const double s = 1e6;
    Strength     strength;
    strength.tensile_strength = 0.5 * s;
    const MaximumPrincipalStress criterion;

    const SymmetricTensor<2, 2> general = tensor(2.5 * s, -1.25 * s, 0.75 * s);
    check_value("sigma_1 vs deal.II eigenvalues",
                largest_principal_stress(general),
                eigenvalues(general)[0],
                s);

    // 0 -> [[1, 1], [1, 1]] MPa: sigma_1 0 -> 2 MPa, reaches T at 1/4.
    // The edge's own normal and shear stress play no part.
    EdgeState start, end;
    end.stress        = tensor(s, s, s);
    end.normal_stress = -3 * s;
    check_failure("crossing",
                  criterion.failure_in_step(start, end, strength),
                  FailureMode::tension,
                  0.25);
    start.stress = tensor(0.6 * s, -s, 0);
    check_failure("beyond T at the start",
                  criterion.failure_in_step(start, end, strength),
                  FailureMode::tension,
                  0.);
    start.stress = tensor(0.4 * s, -s, 0);
    end.stress   = tensor(-s, 0.45 * s, 0.1 * s);
    check_failure("below T at both ends",
                  criterion.failure_in_step(start, end, strength),
                  FailureMode::none);

    // Principal directions swapping within the step: diag(0.5, -1) T ->
    // diag(-1, 2) T. Linear sigma_1: (0.5 - 1)/(0.5 - 2) = 1/3. For the
    // linearly varying tensor sigma_1 = (-1 + 3 t) T reaches T at 2/3: the
    // interpolation of sigma_1 is earlier, never later (convexity).
    const double T = strength.tensile_strength;
    start.stress   = tensor(0.5 * T, -T, 0);
    end.stress     = tensor(-T, 2 * T, 0);
    check_failure("principal directions swap",
                  criterion.failure_in_step(start, end, strength),
                  FailureMode::tension,
                  1. / 3.);
    double low = 0, high = 1;
    for (unsigned int i = 0; i < 100; ++i)
      {
        const double middle = 0.5 * (low + high);
        if (largest_principal_stress((1 - middle) * start.stress +
                                     middle * end.stress) > T)
          high = middle;
        else
          low = middle;
      }
    check_value("crossing of the interpolated tensor (bisection)",
                high,
                2. / 3.);
  }



  // A zero strength makes every failure time 0: the excess starts at 0 and
  // grows with the load, so the earliest failure is the step's start for
  // every edge that fails at all (and the whole block cracks in the first
  // event). The criteria name such a material so that the parameters can
  // refuse it.
  void
  test_zero_strength()
  {
    std::cout << "Zero strength" << std::endl;
    const double s = 1e6;
    Strength     no_cohesion;
    no_cohesion.friction_angle   = 30. * numbers::PI / 180.;
    no_cohesion.tensile_strength = s;
    const MohrCoulomb coulomb;
    EdgeState         start, end;
    // A small shear with a compression it exceeds: fails at the start.
    end.shear_stress  = 1e-3 * s;
    end.normal_stress = -1e-4 * s;
    check_failure("c = 0, slight shear",
                  coulomb.failure_in_step(start, end, no_cohesion),
                  FailureMode::shear,
                  0.);
    const std::string reason = coulomb.fails_under_any_load(no_cohesion);
    std::cout << "  Mohr-Coulomb, c = 0: " << reason << std::endl;
    check(reason.find("Cohesion is 0") != std::string::npos,
          "Mohr-Coulomb names c = 0");

    Strength no_tension         = no_cohesion;
    no_tension.cohesion         = s;
    no_tension.tensile_strength = 0.;
    check(coulomb.fails_under_any_load(no_tension)
              .find("Tensile strength is 0") != std::string::npos,
          "Mohr-Coulomb with cut-off names T = 0");
    check(MohrCoulomb(false).fails_under_any_load(no_tension).empty(),
          "Mohr-Coulomb without cut-off accepts T = 0 (c > 0)");
    check(MaximumPrincipalStress()
              .fails_under_any_load(no_tension)
              .find("Tensile strength is 0") != std::string::npos,
          "maximum principal stress names T = 0");
    check(MaximumPrincipalStress().fails_under_any_load(no_cohesion).empty(),
          "maximum principal stress ignores c");

    Strength positive         = no_tension;
    positive.tensile_strength = 1.;
    check(coulomb.fails_under_any_load(positive).empty(),
          "Mohr-Coulomb accepts c, T > 0");
  }



  void
  test_registry()
  {
    std::cout << "Criterion registry" << std::endl;
    std::cout << "  names: " << fracture_criterion_selection() << std::endl;
    check(fracture_criterion_selection() ==
            "Maximum principal stress|Mohr-Coulomb|Never fails",
          "registered names");
    check(dynamic_cast<MohrCoulomb *>(
            create_fracture_criterion("Mohr-Coulomb").get()) != nullptr,
          "create Mohr-Coulomb");
    check(dynamic_cast<MaximumPrincipalStress *>(
            create_fracture_criterion("Maximum principal stress").get()) !=
            nullptr,
          "create Maximum principal stress");
    check(dynamic_cast<NeverFails *>(
            create_fracture_criterion("Never fails").get()) != nullptr,
          "create a criterion registered by the program");

    const std::string unknown =
      message_of([]() { create_fracture_criterion("Griffith"); });
    std::cout << "  unknown name: " << unknown << std::endl;
    check(unknown.find("Fracture/Criterion: 'Griffith' is not a fracture "
                       "criterion. Known fracture criteria: Maximum principal "
                       "stress, Mohr-Coulomb, Never fails.") !=
            std::string::npos,
          "message for an unknown criterion");
    const std::string twice = message_of([]() {
      register_fracture_criterion("Mohr-Coulomb",
                                  "again",
                                  &MohrCoulomb::declare_parameters,
                                  nullptr);
    });
    check(twice.find("Two fracture criteria are registered under the name "
                     "'Mohr-Coulomb'") != std::string::npos,
          "message for a name registered twice");

    // subsection Fracture from a .prm text.
    ParameterHandler prm;
    ndda::parameters::Fracture::declare_parameters(prm);
    ndda::parameters::Fracture parameters;
    parameters.parse_parameters(prm);
    std::cout << "  defaults: Criterion = " << parameters.criterion_name
              << ", Edge stress = "
              << (parameters.edge_stress_method ==
                      EdgeStressMethod::cell_average ?
                    "cell average" :
                    "nodal average")
              << std::endl;
    check(parameters.criterion_name == "Mohr-Coulomb" &&
            parameters.edge_stress_method == EdgeStressMethod::cell_average,
          "defaults");
    prm.parse_input_from_string(R"(
subsection Fracture
  set Criterion = Mohr-Coulomb
  set Edge stress = nodal average
  subsection Mohr-Coulomb
    set Tension cut-off = false
  end
end
)");
    parameters.parse_parameters(prm);
    check(parameters.edge_stress_method == EdgeStressMethod::nodal_average,
          "Edge stress = nodal average");
    Strength strength;
    strength.cohesion         = 2e6;
    strength.friction_angle   = std::atan(0.5);
    strength.tensile_strength = 1e6;
    check_failure("Tension cut-off = false read from the .prm",
                  parameters.criterion->failure_in_step(state(0, 0),
                                                        state(6e6, 0),
                                                        strength),
                  FailureMode::shear,
                  2. / 3.);
    const std::string bad = message_of([&]() {
      prm.parse_input_from_string("subsection Fracture\n"
                                  "  set Criterion = Griffith\n"
                                  "end\n");
    });
    std::cout << "  set Criterion = Griffith: "
              << (bad.empty() ? "accepted" : "refused") << std::endl;
    check(bad.find("Griffith") != std::string::npos, "Criterion = Griffith");
  }
} // namespace



int
main()
{
  test_traction();
  test_edge_stresses();
  test_mohr_coulomb();
  test_maximum_principal_stress();
  test_zero_strength();
  test_registry();
  std::cout << "OK" << std::endl;
  return 0;
}
