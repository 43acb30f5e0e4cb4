// SPDX-License-Identifier: GPL-3.0-or-later
//
// Uniaxial compression of a specimen with pre-existing flaws (fracture
// issue, thesis 7.4.2 and 7.4.3 with Tables 3 and 4):
// prm/uniaxial_compression_one_crack.prm (one 40 mm flaw at 45 degrees)
// and prm/uniaxial_compression_two_cracks.prm (two 28 mm flaws en
// echelon), a 100 x 200 mm specimen on a roller, its top driven down at
// 0.4 m/s. The thesis calls both examples qualitative: it shows wing
// cracks at the flaws' tips that grow towards the direction of
// compression, a stress-strain curve without figures, and for two flaws
// wings that link the flaws' facing tips.
//
// Measured on one mesh size for both scenes, given on the command line:
// by default 6 mm (2700 cells, about 50 s a scene; the one-flaw scene's
// own, the two-flaw scene has 5 mm), `./ndda.sh validate` adds 4 mm. On a
// 10 mm mesh a wing is one or two edges long and its direction means
// little.
//
// 1. The elastic slope of the mean axial stress against the axial
//    strain, fitted from 0.2 ms (two passes of the P wave through the
//    height) to the first crack. Mean axial stress: -sum_c A_c sigma_yy,c
//    / A (the mean stress theorem: the force on the top face over the
//    width while inertia is small); strain: 1 - h / h0, h the specimen's
//    height. Reference: the same specimen without flaws, run on the same
//    mesh size over the same time window (the clamped top face makes it
//    stiffer than E), and the flaws' compliance for frictional sliding
//    cracks that do not interact, in an infinite plate (Kachanov 1982;
//    plane stress): a flaw of half-length a at beta = 45 degrees to the
//    load, friction mu = tan 20 degrees, slides under
//    tau* = sigma sin b cos b - mu sigma sin^2 b, its mean slip
//    (pi a / 2) 4 tau* / E adds an axial strain
//    (2 pi a^2 / A) (tau* / sigma) sin b cos b sigma / E. So
//    E_flawed / E_intact = 1 / (1 + sum 2 pi a^2 / A (tau*/sigma) sin b cos
//    b): 0.9804 for one flaw, 0.9808 for two. Target: the flawed specimen
//    is softer than the intact one by 0.5 to 5 % (the finite width makes
//    it softer than the dilute estimate; a coarse mesh stiffer).
// 2. The first crack: tensile, within two mean edges of a flaw's tip.
// 3. Wings at every tip (tests/wings.h): where each starts, its kink
//    against the MTS angle of a closed sliding crack (K_I = 0: 70.53
//    degrees from the flaw, turning towards the load), its mean direction
//    within 10 mm (vertical, the direction of compression, is 45 degrees
//    from the flaw). Target: both on the MTS side (20 to 140 degrees);
//    at a tip that faces the other flaw only the kink (the wing runs to
//    the other flaw, item 5). Asserted: a wing at every tip, kinked to
//    the MTS side; the mean directions are reported against the target,
//    not asserted: they follow the mesh (on 5.9 and 6.1 mm meshes the
//    one-flaw scene misses them, on 6 mm it meets them; issue 18).
// 4. The peak of the mean axial stress: below the intact rock's
//    Mohr-Coulomb strength 2 c cos phi / (1 - sin phi) = 62.8 MPa (the
//    flaws weaken it), and the cracked edges at the end.
// 5. Two flaws: whether new cracks link the two flaws, and when.
//
// A run stops at the scene's end time (3 ms) or once the mean axial stress
// has fallen below half its peak (the specimen has failed).

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>

#include "plates.h"
#include "tests.h"
#include "wings.h"

using namespace ndda_tests;
using namespace ndda_tests::wings;

namespace
{
  constexpr double width = 0.1, height = 0.2;

  /** Mean axial (compressive) stress and axial strain, present geometry. */
  std::pair<double, double>
  stress_and_strain(const ndda::Simulator<2> &simulator)
  {
    const auto &mesh = simulator.get_mesh().get_block_mesh();
    double      sum = 0, area = 0, y_min = 1e9, y_max = -1e9;
    for (unsigned int c = 0; c < mesh.triangles.size(); ++c)
      {
        const auto  &t = mesh.triangles[c];
        const auto   a = mesh.vertices[t[1]] - mesh.vertices[t[0]];
        const auto   b = mesh.vertices[t[2]] - mesh.vertices[t[0]];
        const double A = 0.5 * (a[0] * b[1] - a[1] * b[0]);
        area += A;
        sum += A * simulator.mean_cell_stress(c)[1][1];
      }
    for (const auto &v : mesh.vertices)
      {
        y_min = std::min(y_min, v[1]);
        y_max = std::max(y_max, v[1]);
      }
    return {-sum / area, 1 - (y_max - y_min) / height};
  }

  /** Least-squares slope of y over x for the points with t in [t0, t1]. */
  double
  slope(const std::vector<std::array<double, 3>> &curve, // t, strain, stress
        const double                              t0,
        const double                              t1)
  {
    double       sx = 0, sy = 0, sxx = 0, sxy = 0;
    unsigned int n = 0;
    for (const auto &[t, x, y] : curve)
      if (t >= t0 - 1e-12 && t <= t1 + 1e-12)
        {
          sx += x;
          sy += y;
          sxx += x * x;
          sxy += x * y;
          ++n;
        }
    check(n >= 3, "at least three points to fit the elastic slope");
    return (n * sxy - sx * sy) / (n * sxx - sx * sx);
  }

  std::string
  geometry_override(const double mesh_size, const std::string &extra)
  {
    return "subsection Geometry\n  subsection specimen\n    set Mesh size = " +
           std::to_string(mesh_size) + "\n" + extra +
           "  end\nend\nsubsection Output\n  set Interval = 0\nend\n";
  }

  /** The mean edge length of the block mesh at the start. */
  double
  mean_edge(const ndda::Simulator<2> &simulator)
  {
    const auto  &mesh = simulator.get_mesh().get_block_mesh();
    double       sum  = 0;
    unsigned int n    = 0;
    for (const auto &t : mesh.triangles)
      for (unsigned int j = 0; j < 3; ++j, ++n)
        sum += mesh.vertices[t[j]].distance(mesh.vertices[t[(j + 1) % 3]]);
    return sum / n;
  }

  /** The union-find root of @p i. */
  unsigned int
  root(std::vector<unsigned int> &parent, unsigned int i)
  {
    while (parent[i] != i)
      i = parent[i] = parent[parent[i]];
    return i;
  }

  /**
   * Whether the new crack edges join the two flaws: a chain of new edges
   * (in the initial geometry) from a point on one flaw to a point on the
   * other.
   */
  bool
  flaws_linked(const std::vector<NewEdge>                 &edges,
               const std::vector<ndda::geometry::Segment> &flaws)
  {
    if (flaws.size() < 2)
      return false;
    std::vector<Point<2>>     points;
    std::vector<unsigned int> parent = {0, 1}; // 0, 1: the two flaws
    const auto                index  = [&](const Point<2> &p) {
      for (unsigned int k = 0; k < 2; ++k)
        {
          const auto        &f     = flaws[k];
          const double       l     = f.a.distance(f.b);
          const Tensor<1, 2> along = (f.b - f.a) / l;
          const Tensor<1, 2> r     = p - f.a;
          if (std::abs(r[0] * along[1] - r[1] * along[0]) < tolerance &&
              r * along > -tolerance && r * along < l + tolerance)
            return k;
        }
      for (unsigned int i = 0; i < points.size(); ++i)
        if (points[i].distance(p) < tolerance)
          return i + 2;
      points.push_back(p);
      parent.push_back(parent.size());
      return static_cast<unsigned int>(parent.size() - 1);
    };
    for (const auto &[e, step] : edges)
      {
        const unsigned int i = root(parent, index(e[0]));
        const unsigned int j = root(parent, index(e[1]));
        parent[i]            = j;
      }
    return root(parent, 0) == root(parent, 1);
  }

  /** The far-field estimate of E_flawed / E_intact (header, item 1). */
  double
  sliding_crack_ratio(const std::vector<ndda::geometry::Segment> &flaws,
                      const double                                friction)
  {
    double sum = 0;
    for (const auto &f : flaws)
      {
        const double a = 0.5 * f.a.distance(f.b);
        const double b = std::atan2(std::abs(f.b[0] - f.a[0]),
                                    std::abs(f.b[1] - f.a[1])); // from y
        const double s = std::sin(b), c = std::cos(b);
        const double tau = std::max(0., s * c - std::tan(friction) * s * s);
        sum += 2 * M_PI * a * a / (width * height) * tau * s * c;
      }
    return 1 / (1 + sum);
  }

  /** Run the scene without its flaws and without fracture until @p end:
   * the axial stress-strain curve of the intact specimen. */
  std::vector<std::array<double, 3>>
  intact_curve(const std::string &name,
               const double       mesh_size,
               const double       end)
  {
    std::string text = read_example(name);
    text += geometry_override(mesh_size, "    set Cracks =\n");
    text += "subsection Materials\n  subsection rock\n"
            "    set Fracture = false\n  end\nend\n";
    ndda::Simulator<2> simulator(read_parameters(text, name));
    simulator.setup();
    std::vector<std::array<double, 3>> curve;
    while (simulator.get_time() < end - 1e-12)
      {
        simulator.do_time_step();
        const auto [stress, strain] = stress_and_strain(simulator);
        curve.push_back({{simulator.get_time(), strain, stress}});
      }
    return curve;
  }

  void
  run(const std::string &scene, const double mesh_size)
  {
    const auto        wall_start = std::chrono::steady_clock::now();
    const std::string text =
      read_example(scene) + geometry_override(mesh_size, "");
    const auto         parameters = read_parameters(text, scene);
    ndda::Simulator<2> simulator(parameters);
    simulator.setup();
    const double       h     = mean_edge(simulator);
    const auto        &flaws = parameters.geometry.blocks[0].cracks;
    CrackRecorder      recorder(simulator);
    std::ostringstream mm;
    mm << mesh_size * 1e3;
    const std::string key =
      "uniaxial_compression." + scene + "." + mm.str() + "mm.";
    const unsigned int n_cells =
      simulator.get_mesh().get_block_mesh().triangles.size();
    std::cout << scene << ", mesh size " << mesh_size * 1e3
              << " mm: " << n_cells << " cells, mean edge " << h * 1e3
              << " mm, " << flaws.size() << " flaw(s)" << std::endl;
    record(key + "cells", n_cells);
    record(key + "mean_edge", h * 1e3, 3);

    // Run; the stress-strain curve every step.
    std::vector<std::array<double, 3>> curve; // t, strain, stress
    double       peak = 0, peak_time = 0, peak_strain = 0, crack_stress = 0;
    double       link_time    = -1;
    unsigned int link_cracked = 0;
    while (simulator.get_time() < parameters.control.end_time - 1e-12)
      {
        simulator.do_time_step();
        recorder.record();
        const auto [stress, strain] = stress_and_strain(simulator);
        curve.push_back({{simulator.get_time(), strain, stress}});
        if (simulator.get_first_edge_failure().mode ==
            ndda::fracture::FailureMode::none)
          crack_stress = stress;
        if (stress > peak)
          {
            peak        = stress;
            peak_time   = simulator.get_time();
            peak_strain = strain;
          }
        if (link_time < 0 && flaws.size() > 1 && recorder.has_new_cracks() &&
            flaws_linked(recorder.new_edges(), flaws))
          {
            link_time    = simulator.get_time();
            link_cracked = simulator.get_n_cracked_edges();
          }
        if (stress < 0.5 * peak)
          break;
      }
    const double end_time = simulator.get_time();
    const auto  &failure  = simulator.get_first_edge_failure();
    check(failure.mode != ndda::fracture::FailureMode::none,
          "the specimen cracks");

    // 1. The elastic slope.
    const double t0 = 2e-4;
    check(failure.time > t0 + 5e-5,
          "the first crack comes after the elastic window's start");
    const double E        = parameters.materials.materials[0].youngs_modulus;
    const double E_flawed = slope(curve, t0, failure.time);
    const double E_intact =
      slope(intact_curve(scene, mesh_size, failure.time), t0, failure.time);
    const double phi = parameters.materials.joint.friction_angle * M_PI / 180;
    const double expected = sliding_crack_ratio(flaws, phi);
    const double ratio    = E_flawed / E_intact;
    std::cout << "elastic slope from " << t0 * 1e3 << " to "
              << failure.time * 1e3 << " ms: flawed " << E_flawed / 1e9
              << " GPa, intact " << E_intact / 1e9 << " GPa (E = " << E / 1e9
              << " GPa); flawed / intact " << ratio
              << ", sliding cracks in an infinite plate " << expected
              << std::endl;
    record(key + "E_flawed", E_flawed / 1e9, 4);
    record(key + "E_intact", E_intact / 1e9, 4);
    record(key + "E_ratio", ratio, 4);
    record(key + "E_expected", expected, 4);
    record(key + "E_met", met(ratio > 0.95 && ratio < 0.995));

    // 2. The first crack.
    double tip_distance = 1e9;
    for (const auto &f : flaws)
      tip_distance = std::min({tip_distance,
                               failure.location.distance(f.a),
                               failure.location.distance(f.b)});
    std::cout << "first crack at " << failure.time * 1e3 << " ms ("
              << mode_name(failure.mode) << "), mean axial stress "
              << crack_stress / 1e6 << " MPa, " << tip_distance * 1e3
              << " mm from the nearest tip (" << tip_distance / h
              << " mean edges)" << std::endl;
    record(key + "first_time", failure.time * 1e3, 3);
    record(key + "first_stress", crack_stress / 1e6, 3);
    record(key + "first_mode", mode_name(failure.mode));
    record(key + "first_distance", tip_distance * 1e3, 3);
    record(key + "first_edges", tip_distance / h, 3);
    const bool first_met =
      failure.mode == ndda::fracture::FailureMode::tension &&
      tip_distance < 2 * h;
    record(key + "first_met", met(first_met));

    // 3. The wings.
    const std::vector<NewEdge> edges       = recorder.new_edges();
    const double               mts         = mts_angle(0, -1).first;
    const auto                 on_boundary = [](const Point<2> &p) {
      return p[0] < tolerance || p[0] > width - tolerance || p[1] < tolerance ||
             p[1] > height - tolerance;
    };
    unsigned int n_wings = 0, n_wings_met = 0, n_kinks_met = 0;
    for (unsigned int f = 0; f < flaws.size(); ++f)
      for (unsigned int k = 0; k < 2; ++k)
        {
          const Tensor<1, 2> along =
            (flaws[f].b - flaws[f].a) / flaws[f].a.distance(flaws[f].b);
          Wing wing;
          wing.tip     = k == 0 ? flaws[f].b : flaws[f].a;
          wing.outward = k == 0 ? along : -along;
          wing.mts     = mts;
          trace_wing(
            wing, edges, recorder, flaws[f].a, flaws[f].b, 0.01, on_boundary);
          const std::string w = key + "flaw" + std::to_string(f + 1) +
                                (k == 0 ? ".upper." : ".lower.");
          record(w + "found", wing.found ? "yes" : "**no**");
          std::cout << "flaw " << f + 1 << ", " << (k == 0 ? "upper" : "lower")
                    << " tip: ";
          if (!wing.found)
            {
              std::cout << "no wing" << std::endl;
              continue;
            }
          ++n_wings;
          // A tip that faces the other flaw: its wing runs to the other
          // flaw's (item 5), so only its kink counts.
          bool facing = false;
          if (flaws.size() > 1)
            {
              const auto &o      = flaws[1 - f];
              const auto  centre = 0.5 * (o.a + o.b);
              const auto &other  = k == 0 ? flaws[f].a : flaws[f].b;
              facing = wing.tip.distance(centre) < other.distance(centre);
            }
          const bool kinked = wing.kink > 20 && wing.kink < 140;
          const bool ok =
            kinked &&
            (facing || (wing.mean_direction > 20 && wing.mean_direction < 140));
          n_kinks_met += kinked ? 1 : 0;
          n_wings_met += ok ? 1 : 0;
          std::cout << "wing from " << wing.start.distance(wing.tip) * 1e3
                    << " mm behind the tip at "
                    << wing.step * parameters.control.time_step * 1e3
                    << " ms, kink " << wing.kink << " deg (MTS " << mts
                    << "), mean direction within 10 mm " << wing.mean_direction
                    << " deg (" << wing.n_points << " points)"
                    << (facing ? "; faces the other flaw" : "") << std::endl;
          record(w + "start", wing.start.distance(wing.tip) * 1e3, 3);
          record(w + "kink", wing.kink, 4);
          record(w + "mean", wing.mean_direction, 3);
          record(w + "facing", facing ? "yes" : "no");
          record(w + "met", met(ok));
        }

    // 4. Peak and end.
    const double c = parameters.materials.materials[0].cohesion;
    const double fr =
      parameters.materials.materials[0].friction_angle * M_PI / 180;
    const double ucs = 2 * c * std::cos(fr) / (1 - std::sin(fr));
    std::cout << "peak mean axial stress " << peak / 1e6 << " MPa at "
              << peak_time * 1e3 << " ms (strain " << peak_strain
              << "), intact Mohr-Coulomb strength " << ucs / 1e6
              << " MPa; run ended at " << end_time * 1e3 << " ms with "
              << simulator.get_n_cracked_edges() << " cracked edges, "
              << simulator.get_mesh().n_blocks() << " blocks" << std::endl;
    record(key + "peak", peak / 1e6, 3);
    record(key + "peak_time", peak_time * 1e3, 3);
    record(key + "peak_strain", peak_strain * 1e3, 3);
    record(key + "ucs", ucs / 1e6, 3);
    record(key + "peak_met", met(peak < ucs));
    record(key + "end_time", end_time * 1e3, 3);
    record(key + "cracked", simulator.get_n_cracked_edges());
    record(key + "blocks", simulator.get_mesh().n_blocks());

    // 5. Linking.
    if (flaws.size() > 1)
      {
        std::cout << "the flaws are "
                  << (link_time > 0 ? "linked by new cracks at " :
                                      "not linked by new cracks")
                  << (link_time > 0 ? std::to_string(link_time * 1e3) + " ms" :
                                      "")
                  << std::endl;
        record(key + "linked", link_time > 0 ? "yes" : "**no**");
        record(key + "link_time", link_time * 1e3, 3);
        record(key + "link_cracked", link_cracked);
      }
    report_wall_time(key + "run", wall_start);

    check(ratio > 0.95 && ratio < 0.995,
          "the flaws soften the specimen by 0.5 to 5 %");
    check(first_met, "the first crack is tensile, near a flaw's tip");
    // The wings' mean directions are bound to the mesh (the cracks follow
    // its edges, issue 18): reported against the target, not asserted.
    if (n_wings_met < n_wings)
      std::cout << "target NOT met: " << n_wings - n_wings_met << " of "
                << n_wings << " wings do not keep to the MTS side within 10 mm"
                << std::endl;
    check(n_wings == 2 * flaws.size() && n_kinks_met == n_wings,
          "a wing at every tip, kinked to the MTS side");
    check(peak < ucs, "the peak is below the intact strength");
  }
} // namespace

int
main(int argc, char **argv)
{
  using namespace dealii;
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::cout << std::setprecision(4);
  const double mesh_size = argc > 1 ? std::atof(argv[1]) : 0.006;
  check(mesh_size > 0, "a positive mesh size");
  run("uniaxial_compression_one_crack", mesh_size);
  run("uniaxial_compression_two_cracks", mesh_size);
  std::cout << "OK" << std::endl;
}
