// SPDX-License-Identifier: GPL-3.0-or-later
//
// Toppling against sliding (validation atlas): prm/toppling_block.prm, a
// block of base b and height h = 1 m on a fixed 30 degree incline, in the
// four combinations of
//   - friction angle phi = 40 degrees (no sliding: alpha < phi) or below
//     alpha (sliding), and
//   - base b = 0.8 m (standing: b / h > tan alpha = 0.577) or 0.3 m
//     (toppling: b / h < tan alpha),
// the classical rigid-block criteria (Goodman and Bray 1976). Those are
// static; a block that topples needs less friction at its pivot than one
// at rest. A rigid block starting to turn about its downhill corner P
// (slope coordinates, the corner's reaction N normal and F along the
// slope) has psi''_0 = 3 g (h sin alpha - b cos alpha) / (2 (b^2 + h^2)),
// N = m (g cos alpha + psi''_0 b / 2) and F = m (g sin alpha - psi''_0 h /
// 2): it slides as it topples only if F / N > tan phi, which is 0.366
// (20.1 degrees) for b = 0.3 m. And a block that slides feels, in its own
// accelerating frame, gravity tilted by phi from the slope's normal: it
// topples while sliding only if b / h < tan phi (0.3 < tan phi: phi >
// 16.7 degrees). So the slender block slides and topples only for phi
// between 16.7 and 20.1 degrees: at 18 degrees. At 20 degrees (static:
// "slides and topples") it only topples, at 10 degrees it only slides;
// the test runs all three.
//
// Measured from two measure points, the block's centroid C and its top
// downhill corner: the block's rotation psi (counter-clockwise, i.e.
// toppling downhill, positive) and the slide of its downhill base corner
// along the slope (that corner moved rigidly with C and psi).
// References:
//  - sliding without toppling: the slide s = g (sin alpha - cos alpha
//    tan phi) t^2 / 2;
//  - toppling without sliding: a rigid body turning about the fixed
//    corner P, I_P psi'' = -m g (C_x(psi) - P_x), I_P = m (b^2 + h^2) / 3,
//    integrated here (RK4, 1e-5 s).
// Asserted at t = 0.3 s: standing: |psi| < 0.1 deg and slide < 1 mm;
// sliding: |psi| < 0.5 deg and the slide within 5 % of the formula;
// toppling (phi = 40 and 20 degrees): psi within 10 % of the rigid body's
// and the corner's slide below 2 mm; sliding and toppling (phi = 18
// degrees): psi > 1 deg and slide > 1 cm; sliding only (phi = 10
// degrees): |psi| < 0.5 deg and the slide within 5 % of the formula.
// The six cases run with the block meshed, affine (Shi's DDA block) and
// rigid (`Kinematics`), against the same targets.

#include <array>
#include <cmath>

#include "tests.h"

using namespace ndda_tests;

namespace
{
  constexpr double alpha = M_PI / 6, h = 1, g = 9.81, s0 = 2.0;
  constexpr double end = 0.3;

  /** A point s along the slope from its foot and z above it. */
  std::array<double, 2>
  on_slope(const double s, const double z)
  {
    return {{s * std::cos(alpha) - z * std::sin(alpha),
             s * std::sin(alpha) + z * std::cos(alpha)}};
  }

  std::string
  xy(const std::array<double, 2> &p)
  {
    std::ostringstream text;
    text << std::setprecision(17) << p[0] << ", " << p[1];
    return text.str();
  }

  /** The rigid block's rotation about its downhill corner at time t. */
  double
  rigid_toppling(const double b, const double t)
  {
    // C - P at psi = 0, in the global frame.
    const auto   c  = on_slope(b / 2, h / 2);
    const auto   p  = on_slope(0, 0);
    const double rx = c[0] - p[0], ry = c[1] - p[1];
    const double k            = 3 * g / (b * b + h * h); // m g / I_P
    const auto   acceleration = [&](const double psi) {
      return -k * (std::cos(psi) * rx - std::sin(psi) * ry);
    };
    double       psi = 0, omega = 0;
    const double dt = 1e-5;
    for (double time = 0; time < t - 1e-12; time += dt)
      {
        const double k1p = omega, k1w = acceleration(psi);
        const double k2p = omega + dt / 2 * k1w,
                     k2w = acceleration(psi + dt / 2 * k1p);
        const double k3p = omega + dt / 2 * k2w,
                     k3w = acceleration(psi + dt / 2 * k2p);
        const double k4p = omega + dt * k3w, k4w = acceleration(psi + dt * k3p);
        psi += dt / 6 * (k1p + 2 * k2p + 2 * k3p + k4p);
        omega += dt / 6 * (k1w + 2 * k2w + 2 * k3w + k4w);
      }
    return psi;
  }

  struct Motion
  {
    double psi = 0, slide = 0; // degrees, m (downhill positive)
  };

  Motion
  run(const double b, const double phi, const std::string &model)
  {
    const auto  p0 = on_slope(s0, 0), p1 = on_slope(s0 + b, 0);
    const auto  p2 = on_slope(s0 + b, h), p3 = on_slope(s0, h);
    const auto  c    = on_slope(s0 + b / 2, h / 2);
    std::string text = read_example("toppling_block");
    text += "subsection Control\n  set End time = " + std::to_string(end) +
            "\nend\n"
            "subsection Materials\n  subsection Joint\n"
            "    set Friction angle = " +
            std::to_string(phi) +
            "\n  end\nend\n"
            "subsection Geometry\n  subsection incline\n"
            "    set Outer boundary = 0, 0; 4.3301270189221936, 0; "
            "4.3301270189221936, 2.4999999999999996"
            "\n  end\n  subsection block\n    set Outer boundary = " +
            xy(p0) + "; " + xy(p1) + "; " + xy(p2) + "; " + xy(p3) +
            "\n    set Kinematics = " + model +
            "\n  end\nend\n"
            "subsection Output\n  set Interval = 0\n  set Write vtu = false\n"
            "  set Measure points = " +
            xy(c) + "; " + xy(p3) + "\nend\n";
    ndda::Simulator<2> simulator(read_parameters(text, "toppling_block"));
    simulator.setup();
    while (simulator.get_time() < end - 1e-12)
      simulator.do_time_step();
    const auto &uc = simulator.get_measure_histories()[0].back().displacement;
    const auto &ut = simulator.get_measure_histories()[1].back().displacement;
    // Rotation of the vector centroid -> top downhill corner.
    const double x0 = p3[0] - c[0], y0 = p3[1] - c[1];
    const double x1 = x0 + ut[0] - uc[0], y1 = y0 + ut[1] - uc[1];
    const double psi = std::atan2(x0 * y1 - y0 * x1, x0 * x1 + y0 * y1);
    // The downhill base corner moved rigidly with C and psi.
    const double rx = p0[0] - c[0], ry = p0[1] - c[1];
    const double dx = uc[0] + std::cos(psi) * rx - std::sin(psi) * ry - rx;
    const double dy = uc[1] + std::sin(psi) * rx + std::cos(psi) * ry - ry;
    Motion       motion;
    motion.psi   = psi * 180 / M_PI;
    motion.slide = -(dx * std::cos(alpha) + dy * std::sin(alpha));
    return motion;
  }

  /**
   * Record a block that should slide without turning (under @p key: its
   * rotation, slide, the rigid block's slide @p reference and the error)
   * and return whether it meets the target: |psi| < 0.5 deg, the slide
   * within 5 % of the reference.
   */
  bool
  slides_as_rigid_block(const std::string &key,
                        const Motion      &motion,
                        const double       reference)
  {
    const bool ok = std::abs(motion.psi) < 0.5 &&
                    std::abs(motion.slide / reference - 1) < 0.05;
    record(key + "psi", motion.psi, 2);
    record(key + "slide", motion.slide * 1e3, 4);
    record(key + "reference", reference * 1e3, 4);
    record(key + "error", 100 * (motion.slide / reference - 1), 2);
    record(key + "met", met(ok));
    return ok;
  }



  /**
   * Record a block that should topple about its downhill corner without
   * sliding (under @p key: its rotation, the error against the rigid
   * block's rotation @p reference and the corner's slide) and return
   * whether it meets the target: the rotation within 10 %, the slide
   * below 2 mm.
   */
  bool
  topples_as_rigid_block(const std::string &key,
                         const Motion      &motion,
                         const double       reference)
  {
    const bool ok = std::abs(motion.psi / reference - 1) < 0.1 &&
                    std::abs(motion.slide) < 2e-3;
    record(key + "psi", motion.psi, 4);
    record(key + "error", 100 * (motion.psi / reference - 1), 2);
    record(key + "slide", motion.slide * 1e3, 2);
    record(key + "met", met(ok));
    return ok;
  }



  /**
   * The six cases with the block modelled as @p model (Control/Kinematics:
   * meshed, affine or rigid; the incline is rigid in every run), their
   * figures recorded under @p key; the same targets for every model.
   */
  void
  cases(const std::string &model, const std::string &key)
  {
    const Motion standing = run(0.8, 40, model);
    std::cout << model << ": b = 0.8 m, phi = 40 deg (stands): rotation "
              << standing.psi << " deg, slide " << standing.slide * 1e3
              << " mm at " << end << " s" << std::endl;
    record(key + "standing.psi", standing.psi, 2);
    record(key + "standing.slide", standing.slide * 1e3, 2);
    record(key + "standing.met",
           met(std::abs(standing.psi) < 0.1 &&
               std::abs(standing.slide) < 1e-3));

    const Motion sliding = run(0.8, 20, model);
    const double slide_reference =
      g * (std::sin(alpha) - std::cos(alpha) * std::tan(20 * M_PI / 180)) *
      end * end / 2;
    std::cout << model << ": b = 0.8 m, phi = 20 deg (slides): rotation "
              << sliding.psi << " deg, slide " << sliding.slide * 1e3
              << " mm (rigid block " << slide_reference * 1e3 << " mm, error "
              << 100 * (sliding.slide / slide_reference - 1) << " %)"
              << std::endl;
    const bool slides =
      slides_as_rigid_block(key + "sliding.", sliding, slide_reference);

    const Motion toppling           = run(0.3, 40, model);
    const double toppling_reference = rigid_toppling(0.3, end) * 180 / M_PI;
    std::cout << model << ": b = 0.3 m, phi = 40 deg (topples): rotation "
              << toppling.psi << " deg (rigid body about the corner "
              << toppling_reference << " deg, error "
              << 100 * (toppling.psi / toppling_reference - 1)
              << " %), corner slide " << toppling.slide * 1e3 << " mm"
              << std::endl;
    record(key + "toppling.reference", toppling_reference, 4);
    const bool topples =
      topples_as_rigid_block(key + "toppling.", toppling, toppling_reference);

    const Motion marginal = run(0.3, 20, model);
    std::cout
      << model
      << ": b = 0.3 m, phi = 20 deg (topples, does not slide): rotation "
      << marginal.psi << " deg (rigid body " << toppling_reference
      << " deg), corner slide " << marginal.slide * 1e3 << " mm" << std::endl;
    const bool marginal_topples =
      topples_as_rigid_block(key + "marginal.", marginal, toppling_reference);

    const Motion slender_sliding = run(0.3, 10, model);
    const double slide_10 =
      g * (std::sin(alpha) - std::cos(alpha) * std::tan(10 * M_PI / 180)) *
      end * end / 2;
    std::cout
      << model
      << ": b = 0.3 m, phi = 10 deg (slides, does not topple): rotation "
      << slender_sliding.psi << " deg, slide " << slender_sliding.slide * 1e3
      << " mm (rigid block " << slide_10 * 1e3 << " mm)" << std::endl;
    const bool slender_slides = slides_as_rigid_block(key + "slender_sliding.",
                                                      slender_sliding,
                                                      slide_10);

    const Motion both = run(0.3, 18, model);
    std::cout << model
              << ": b = 0.3 m, phi = 18 deg (slides and topples): rotation "
              << both.psi << " deg, corner slide " << both.slide * 1e3 << " mm"
              << std::endl;
    record(key + "both.psi", both.psi, 3);
    record(key + "both.slide", both.slide * 1e3, 3);
    record(key + "both.met", met(both.psi > 1 && both.slide > 1e-2));

    check(std::abs(standing.psi) < 0.1 && std::abs(standing.slide) < 1e-3,
          model + ": the wide block on the rough slope stands");
    check(slides,
          model +
            ": the wide block on the smooth slope slides as a rigid block");
    check(topples,
          model +
            ": the slender block on the rough slope topples about its corner");
    check(marginal_topples,
          model +
            ": at phi = 20 degrees the slender block topples without sliding");
    check(slender_slides,
          model +
            ": at phi = 10 degrees the slender block slides without toppling");
    check(both.psi > 1 && both.slide > 1e-2,
          model + ": the slender block on the smooth slope slides and topples");
  }
} // namespace

int
main(int argc, char **argv)
{
  using namespace dealii;
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::cout << std::setprecision(4);
  const auto wall_start = std::chrono::steady_clock::now();

  // The friction ratio the slender block's pivot needs at the start.
  const double psi0 = 3 * g * (h * std::sin(alpha) - 0.3 * std::cos(alpha)) /
                      (2 * (0.3 * 0.3 + h * h));
  const double needed = (g * std::sin(alpha) - psi0 * h / 2) /
                        (g * std::cos(alpha) + psi0 * 0.3 / 2);
  std::cout << "b = 0.3 m: the pivot needs F / N = " << needed << " ("
            << std::atan(needed) * 180 / M_PI << " deg) at the start"
            << std::endl;
  record("toppling_block.needed_angle", std::atan(needed) * 180 / M_PI, 3);
  cases("meshed", "toppling_block.");
  // The same cases with the block as Shi's DDA block and as a rigid block
  // (issue 15: every contact case with every model).
  for (const std::string model : {"affine", "rigid"})
    cases(model, "toppling_block." + model + ".");
  report_wall_time("toppling_block", wall_start);
  std::cout << "OK" << std::endl;
}
