// SPDX-License-Identifier: GPL-3.0-or-later
//
// Brazilian disc with a central hole (fracture issue, thesis 7.5.4 with
// Table 7): prm/brazilian_disc_hole.prm, a 50 mm disc, 25 mm thick, with a
// hole of radius a = 5 mm at its centre, between two stiff plates, the top
// one driven down at 0.1 m/s.
//
// Reference: the ring test. Diametral loads P on a ring of outer radius R
// and inner radius a, thickness t, put the largest tension at the hole's
// top and bottom, on the loaded diameter, in the hoop direction (here
// sigma_xx). For a small hole it is 6 P / (pi R t): the intact disc's
// centre carries sigma_xx = P / (pi R t) and sigma_yy = -3 P / (pi R t),
// and Kirsch's hole in that biaxial field gives 3 sigma_xx - sigma_yy.
// Hobbs (1965, from the exact series solution for a ring) fitted
//     sigma_max = (6 + 38 (a/R)^2) P / (pi R t),
// 7.52 P / (pi R t) for a/R = 0.2.
//
// 1. Before the first crack: the stress at the hole's top and bottom
//    (the nodal stress there: the area-weighted mean of the cells around
//    the vertex, as the 'nodal average' edge stress takes it) against
//    Hobbs, for the plate
//    force P measured from the plates' mean stress (tests/plates.h). A
//    P1 cell carries the mean of a field that falls steeply away from the
//    hole (Kirsch: to 80 % of the peak one third of a millimetre away),
//    so on the scene's mesh the measured stress lies below the peak; a
//    run with the hole's boundary and the mesh twice as fine (fracture
//    off) must come closer to it.
// 2. The first crack: tensile, at the hole's top or bottom (on the loaded
//    diameter, within one cell of the hole), as in the thesis and in Van
//    de Steen et al. (2005).
// 3. Then cracks run from the hole along the loaded diameter to within
//    0.15 R of both plates, and the disc falls apart.

#include <algorithm>
#include <chrono>
#include <cmath>

#include "plates.h"
#include "tests.h"

using namespace ndda_tests;

namespace
{
  constexpr double D = 0.05, R = D / 2, a = 0.005, T = 12e6;

  /** Hobbs's largest hoop stress at the hole for the force P. */
  double
  hobbs(const double p, const double t)
  {
    return (6 + 38 * (a / R) * (a / R)) * p / (M_PI * R * t);
  }

  /**
   * sigma_xx at the vertex nearest to @p p: the area-weighted mean over
   * the cells around it (the nodal stress of the 'nodal average' edge
   * stress, fracture/edge_stress.h).
   */
  double
  nodal_sigma_xx(const ndda::Simulator<2> &simulator, const dealii::Point<2> &p)
  {
    const auto  &mesh = simulator.get_mesh().get_block_mesh();
    unsigned int v    = 0;
    for (unsigned int i = 1; i < mesh.vertices.size(); ++i)
      if (mesh.vertices[i].distance(p) < mesh.vertices[v].distance(p))
        v = i;
    double sum = 0, area = 0;
    for (unsigned int c = 0; c < mesh.triangles.size(); ++c)
      {
        const auto &t = mesh.triangles[c];
        if (std::find(t.begin(), t.end(), v) == t.end())
          continue;
        const auto   e1 = mesh.vertices[t[1]] - mesh.vertices[t[0]];
        const auto   e2 = mesh.vertices[t[2]] - mesh.vertices[t[0]];
        const double A  = 0.5 * (e1[0] * e2[1] - e1[1] * e2[0]);
        sum += A * simulator.mean_cell_stress(c)[0][0];
        area += A;
      }
    return sum / area;
  }

  /** The hole as a polygon of @p n vertices, one at the top. */
  std::string
  hole_polygon(const unsigned int n)
  {
    std::ostringstream text;
    text << std::setprecision(12);
    for (unsigned int k = 0; k < n; ++k)
      text << (k > 0 ? "; " : "") << a * std::cos(2 * M_PI * k / n) << ", "
           << a * std::sin(2 * M_PI * k / n);
    return text.str();
  }

  struct Elastic
  {
    unsigned int n_cells   = 0;
    double       ratio_top = 0, ratio_bottom = 0; // measured / Hobbs
    double       p = 0;
  };

  /**
   * The scene without fracture to @p end_time, the hole a polygon of @p n
   * vertices, the disc's mesh size @p h: the stress at the hole's top and
   * bottom against Hobbs's, at the end. Printed at a few times.
   */
  Elastic
  elastic(const unsigned int n, const double h, const double end_time)
  {
    std::string text = read_example("brazilian_disc_hole");
    text += "subsection Output\n  set Interval = 0\nend\n"
            "subsection Control\n  set End time = " +
            std::to_string(end_time) +
            "\nend\n"
            "subsection Materials\n  subsection rock\n"
            "    set Fracture = false\n  end\nend\n"
            "subsection Geometry\n  subsection disc\n    set Holes = " +
            hole_polygon(n) + "\n    set Mesh size = " + std::to_string(h) +
            "\n  end\nend\n";
    const auto   parameters = read_parameters(text, "brazilian_disc_hole");
    const double t          = parameters.materials.thickness;
    ndda::Simulator<2> simulator(parameters);
    simulator.setup();
    const unsigned int top = block_index(simulator, "top");
    Elastic            result;
    const auto        &cells = simulator.get_mesh().get_block_mesh().cell_block;
    result.n_cells =
      std::count(cells.begin(), cells.end(), block_index(simulator, "disc"));
    std::cout << "without fracture, hole " << n << "-gon, mesh size " << h * 1e3
              << " mm, " << result.n_cells
              << " cells in the disc: sigma_xx at the hole's top (bottom) "
              << "against Hobbs" << std::endl;
    unsigned int step = 0;
    while (simulator.get_time() < end_time - 1e-12)
      {
        simulator.do_time_step();
        const double p = plate_force(simulator, top);
        result.p       = p;
        result.ratio_top =
          nodal_sigma_xx(simulator, dealii::Point<2>(0, a)) / hobbs(p, t);
        result.ratio_bottom =
          nodal_sigma_xx(simulator, dealii::Point<2>(0, -a)) / hobbs(p, t);
        if (++step % 20 == 0)
          std::cout << "  t = " << simulator.get_time() * 1e3
                    << " ms: P = " << p / 1e3
                    << " kN, Hobbs = " << hobbs(p, t) / 1e6
                    << " MPa, measured / Hobbs = " << result.ratio_top << " ("
                    << result.ratio_bottom << ")" << std::endl;
      }
    return result;
  }
} // namespace

int
main(int argc, char **argv)
{
  using namespace dealii;
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::cout << std::setprecision(4);
  const auto wall_start = std::chrono::steady_clock::now();

  // 1. The stress at the hole before it cracks, on the scene's mesh and on
  //    one twice as fine.
  const Elastic coarse = elastic(32, 0.0022, 4e-4);
  const Elastic fine   = elastic(64, 0.0011, 4e-4);
  std::cout << "at 0.4 ms: measured / Hobbs " << coarse.ratio_top << " ("
            << coarse.ratio_bottom << ") on the scene's mesh, "
            << fine.ratio_top << " (" << fine.ratio_bottom
            << ") on the finer one" << std::endl;
  const std::string key = "brazilian_disc_hole.";
  record(key + "coarse_cells", coarse.n_cells);
  record(key + "fine_cells", fine.n_cells);
  record(key + "coarse_top", coarse.ratio_top, 3);
  record(key + "coarse_bottom", coarse.ratio_bottom, 3);
  record(key + "fine_top", fine.ratio_top, 3);
  record(key + "fine_bottom", fine.ratio_bottom, 3);
  record(key + "coarse_met",
         met(coarse.ratio_top < 1 && coarse.ratio_bottom < 1));
  record(key + "fine_met",
         met(std::abs(fine.ratio_top - 1) < std::abs(coarse.ratio_top - 1) &&
             std::abs(fine.ratio_bottom - 1) <
               std::abs(coarse.ratio_bottom - 1)));
  check(coarse.ratio_top < 1 && coarse.ratio_bottom < 1,
        "P1 cells at the hole carry less than the peak stress");
  check(std::abs(fine.ratio_top - 1) < std::abs(coarse.ratio_top - 1) &&
          std::abs(fine.ratio_bottom - 1) < std::abs(coarse.ratio_bottom - 1),
        "the finer mesh comes closer to Hobbs's stress");

  // 2-3. The scene, until cracks have run from the hole to both plates.
  {
    std::string text = read_example("brazilian_disc_hole");
    text += "subsection Output\n  set Interval = 0\nend\n";
    const auto   parameters = read_parameters(text, "brazilian_disc_hole");
    const double t          = parameters.materials.thickness;
    ndda::Simulator<2> simulator(parameters);
    simulator.setup();
    const unsigned int top     = block_index(simulator, "top");
    double             p_crack = 0, s_top = 0, s_bottom = 0;
    double             crack_time = -1, through_time = -1;
    double             y_low = 0, y_high = 0;
    unsigned int       n_near = 0, n_far = 0;
    while (simulator.get_time() < parameters.control.end_time - 1e-12 &&
           through_time < 0)
      {
        simulator.do_time_step();
        if (simulator.get_n_cracked_edges() == 0)
          {
            // The last step before the first crack.
            p_crack  = plate_force(simulator, top);
            s_top    = nodal_sigma_xx(simulator, dealii::Point<2>(0, a));
            s_bottom = nodal_sigma_xx(simulator, dealii::Point<2>(0, -a));
            continue;
          }
        if (crack_time < 0)
          crack_time = simulator.get_time();
        // Crack faces within 0.2 R of the loaded diameter, above and
        // below the hole, and elsewhere.
        const DiameterCracks cracks = diameter_cracks(simulator, 0.2 * R);
        n_near = cracks.n_near, n_far = cracks.n_far;
        y_low = cracks.y_low, y_high = cracks.y_high;
        if (y_low < -0.85 * R && y_high > 0.85 * R)
          through_time = simulator.get_time();
      }
    check(crack_time > 0, "the disc cracks before the end time");
    const auto  &failure = simulator.get_first_edge_failure();
    const double x = failure.location[0], y = failure.location[1];
    std::cout << "first crack at t = " << failure.time * 1e3 << " ms ("
              << mode_name(failure.mode) << ") at x = " << x * 1e3
              << " mm, y = " << y * 1e3 << " mm; P = " << p_crack / 1e3
              << " kN; the step before: sigma_xx at the hole's top "
              << s_top / 1e6 << " MPa, bottom " << s_bottom / 1e6
              << " MPa, Hobbs " << hobbs(p_crack, t) / 1e6
              << " MPa; Hobbs reaches T = " << T / 1e6
              << " MPa at P = " << T / hobbs(1, t) / 1e3 << " kN" << std::endl;
    record(key + "first_time", failure.time * 1e3);
    record(key + "first_mode", mode_name(failure.mode));
    record(key + "first_x", x * 1e3, 2);
    record(key + "first_y", y * 1e3, 4);
    record(key + "first_p", p_crack / 1e3, 3);
    record(key + "hobbs_p", T / hobbs(1, t) / 1e3, 3);
    record(key + "first_p_excess", 100 * (p_crack * hobbs(1, t) / T - 1), 2);
    record(key + "first_top", s_top / 1e6, 3);
    record(key + "first_bottom", s_bottom / 1e6, 3);
    record(key + "first_met",
           met(failure.mode == ndda::fracture::FailureMode::tension &&
               std::abs(x) < 0.15 * R && std::abs(std::abs(y) - a) < 0.003));
    check(failure.mode == ndda::fracture::FailureMode::tension,
          "the first crack is tensile");
    check(std::abs(x) < 0.15 * R, "the first crack is on the loaded diameter");
    check(std::abs(std::abs(y) - a) < 0.003,
          "the first crack is at the hole's top or bottom");
    std::cout << "cracks along the loaded diameter (|x| < 0.2 R) from y = "
              << y_low / R << " R to " << y_high / R << " R (" << n_near
              << " faces), elsewhere " << n_far << " faces, "
              << (through_time > 0 ? (through_time - crack_time) * 1e3 : -1.)
              << " ms after the first crack; "
              << simulator.get_mesh().n_blocks() << " blocks" << std::endl;
    record(key + "y_low", y_low / R, 2);
    record(key + "y_high", y_high / R, 2);
    record(key + "n_near", n_near);
    record(key + "n_far", n_far);
    record(key + "through_after", (through_time - crack_time) * 1e3, 3);
    record(key + "through_met", met(through_time > 0 && n_near > 2 * n_far));
    check(through_time > 0,
          "cracks run from the hole along the loaded diameter to within "
          "0.15 R of both plates");
    check(n_near > 2 * n_far, "most cracks lie along the loaded diameter");
  }

  report_wall_time("brazilian_disc_hole", wall_start);
  std::cout << "OK" << std::endl;
}
