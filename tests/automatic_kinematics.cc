// SPDX-License-Identifier: GPL-3.0-or-later
//
// Kinematics = auto (issue 15; doc/theory.md, "Automatic kinematics"):
// blocks that start as affine (or rigid) blocks, are meshed when a stress
// of theirs comes near their strength, and return when unloaded.
//
//  1. The indicator's parts against closed forms: near_failure() with the
//     maximum principal stress criterion (uniaxial tension at any angle:
//     near at fraction f exactly when sigma / f exceeds the tensile
//     strength) and with Mohr-Coulomb (uniaxial compression: near when
//     P / f exceeds 2 c cos(phi) / (1 - sin(phi))); boundary_stress()
//     carries the traction and keeps the stress along the boundary.
//  2. A boulder dropped at 5 m/s onto two stacked blocks on a fixed base,
//     every block auto: until the impact the run is the all-affine run to
//     round-off; the impact promotes blocks within the step it happens
//     in, they return to the affine model once unloaded, and the
//     boulder's rebound matches the all-meshed run. Also with Start model
//     = rigid.
//  3. prm/wall_impact.prm (198 bricks, a boulder strikes the top): auto
//     against all-meshed. Every block's centroid at 0.3 s within 1 % of
//     the scene's size of the meshed run's; only blocks near the impact
//     are meshed; the costs of both runs.

#include <ndda/kinematics/automatic_kinematics.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "tests.h"

using namespace ndda_tests;
using namespace dealii;

namespace
{
  /** The area-weighted centroid of every block on the present geometry. */
  std::vector<Point<2>>
  block_centroids(const ndda::Simulator<2> &simulator)
  {
    const auto           &mesh = simulator.get_mesh().get_block_mesh();
    std::vector<Point<2>> centroid(simulator.get_mesh().n_blocks());
    std::vector<double>   area(centroid.size(), 0.);
    for (unsigned int c = 0; c < mesh.triangles.size(); ++c)
      {
        const auto        &t = mesh.triangles[c];
        const Tensor<1, 2> a = mesh.vertices[t[1]] - mesh.vertices[t[0]];
        const Tensor<1, 2> b = mesh.vertices[t[2]] - mesh.vertices[t[0]];
        const double       A = 0.5 * std::abs(a[0] * b[1] - a[1] * b[0]);
        for (const unsigned int v : t)
          centroid[mesh.cell_block[c]] += A / 3. * mesh.vertices[v];
        area[mesh.cell_block[c]] += A;
      }
    for (unsigned int b = 0; b < centroid.size(); ++b)
      centroid[b] /= area[b];
    return centroid;
  }

  /** Case 1: near_failure() and boundary_stress(). */
  void
  check_indicator()
  {
    using namespace ndda;
    std::cout << "1. indicator" << std::endl;
    const auto principal =
      fracture::create_fracture_criterion("Maximum principal stress");
    fracture::Strength strength;
    strength.tensile_strength = 4e6;
    strength.cohesion         = 1e12;
    for (const double angle : {0., 0.3, 1.2, 2.5})
      for (const double ratio : {0.99, 1.01})
        {
          // Uniaxial tension of ratio * f * T along the angle, f = 0.5.
          const double s = ratio * 0.5 * 4e6, c = std::cos(angle),
                       n = std::sin(angle);
          SymmetricTensor<2, 2> stress;
          stress[0][0] = s * c * c;
          stress[1][1] = s * n * n;
          stress[0][1] = s * c * n;
          check(kinematics::near_failure(*principal, strength, stress, 0.5) ==
                  (ratio > 1.),
                "uniaxial tension " + std::to_string(ratio) +
                  " of the limit at angle " + std::to_string(angle));
        }

    const auto mohr   = fracture::create_fracture_criterion("Mohr-Coulomb");
    strength.cohesion = 2e6;
    strength.friction_angle = numbers::PI / 6.;
    const double limit =
      2. * 2e6 * std::cos(numbers::PI / 6.) / (1. - std::sin(numbers::PI / 6.));
    for (const double ratio : {0.99, 1.01})
      {
        SymmetricTensor<2, 2> stress;
        stress[1][1] = -ratio * 0.25 * limit;
        check(kinematics::near_failure(*mohr, strength, stress, 0.25) ==
                (ratio > 1.),
              "uniaxial compression " + std::to_string(ratio) +
                " of the Mohr-Coulomb limit");
      }

    SymmetricTensor<2, 2> stress;
    stress[0][0] = 1.5e6;
    stress[1][1] = -2e6;
    stress[0][1] = 0.7e6;
    const Tensor<1, 2> n({0.6, 0.8}), t({-0.8, 0.6});
    const Tensor<1, 2> traction({-3e6, 1e6});
    const auto         local = kinematics::boundary_stress(stress, n, traction);
    check_value("boundary stress n: x", (local * n)[0], traction[0], 1e6);
    check_value("boundary stress n: y", (local * n)[1], traction[1], 1e6);
    check_value("boundary stress t.t", t * (local * t), t * (stress * t), 1e6);
  }

  const std::string drop = R"(
subsection Control
  set Analysis type   = dynamic
  set Time integrator = DDA
  set Time step       = 1e-3
  set End time        = 0.2
  set Maximum displacement ratio = 0.01
  set Kinematics      = {model}
  subsection Automatic kinematics
    set Start model    = {start}
    set Demotion steps = 20
  end
end
subsection Contact
  set Penalty factor = 10
end
subsection Materials
  set Names = rock
  subsection rock
    set Density          = 2600
    set Young's modulus  = 10e9
    set Poisson's ratio  = 0.25
    set Friction angle   = 35
    set Cohesion         = 20e6
    set Tensile strength = 1e6
    set Fracture         = true
  end
  subsection Joint
    set Friction angle = 35
  end
end
subsection Geometry
  set Blocks = base, lower, upper, boulder
  subsection base
    set Outer boundary = -1, -1; 3, -1; 3, 0; -1, 0
    set Material  = rock
    set Mesh size = 0.5
  end
  subsection lower
    set Outer boundary = 0, 0; 1, 0; 1, 0.5; 0, 0.5
    set Material  = rock
    set Mesh size = 0.5
  end
  subsection upper
    set Outer boundary = 0, 0.5; 1, 0.5; 1, 1; 0, 1
    set Material  = rock
    set Mesh size = 0.5
  end
  subsection boulder
    set Outer boundary = 0.2, 1.02; 0.8, 1.02; 0.8, 1.62; 0.2, 1.62
    set Material  = rock
    set Mesh size = 0.5
    set Initial velocity = 0; -5
  end
end
subsection Loads
  set Gravity = 0; -9.81
end
subsection Boundary conditions
  set Names = ground
  subsection ground
    set Type     = fixed
    set Segments = -1, -1, 3, -1
  end
end
subsection Output
  set Write vtu = false
  set Measure points = 0.5, 1.32; 0.5, 0.75
end
)";

  /** Case 2: the boulder dropped on two blocks. */
  void
  check_drop()
  {
    std::cout << "2. boulder dropped on two blocks" << std::endl;
    std::map<std::string, std::vector<ndda::MeasureSample>> boulder;
    unsigned int                                            first_promotion = 0;
    for (const std::string model : {"affine", "meshed", "auto", "rigid auto"})
      {
        const bool         automatic = model.find("auto") != std::string::npos;
        ndda::Simulator<2> simulator(read_parameters(
          substitute(drop,
                     {{"model", automatic ? "auto" : model},
                      {"start", model == "rigid auto" ? "rigid" : "affine"}}),
          "drop"));
        simulator.keep_measure_histories(); // the whole history
        simulator.setup();
        unsigned int most_meshed = 0;
        while (simulator.get_time() < 0.2 - 1e-12)
          {
            simulator.do_time_step();
            const auto &a = simulator.get_automatic_kinematics();
            if (model == "auto" && first_promotion == 0 && a.n_promotions() > 0)
              first_promotion = simulator.get_step_number();
            const auto meshed = simulator.get_discretization().meshed_blocks();
            most_meshed       = std::max<unsigned int>(
              most_meshed, std::count(meshed.begin(), meshed.end(), true));
          }
        boulder[model] = simulator.get_measure_histories()[0];
        const auto &a  = simulator.get_automatic_kinematics();
        std::cout << "  " << model << ": rebound velocity "
                  << boulder[model].back().velocity[1] << " m/s, height "
                  << boulder[model].back().displacement[1] << " m; promotions "
                  << a.n_promotions() << ", demotions " << a.n_demotions()
                  << ", most meshed " << most_meshed << std::endl;
        if (!automatic)
          continue;
        const std::string key = model == "auto" ? "drop" : "drop_rigid";
        record("automatic_kinematics." + key + ".promotions", a.n_promotions());
        record("automatic_kinematics." + key + ".demotions", a.n_demotions());
        check(a.n_promotions() >= 1, model + ": the impact promotes");
        check(a.n_demotions() >= 1, model + ": unloaded blocks return");
        check(simulator.energy_error() <=
                1e-6 * simulator.work_of_loads() + 1e-9,
              model + ": no energy gained");
      }

    // Until the impact the auto run is the affine run.
    check(first_promotion >= 3, "the boulder falls free for a few steps");
    double before = 0;
    for (unsigned int s = 0; s < first_promotion; ++s)
      before = std::max(before,
                        (boulder["auto"][s].displacement -
                         boulder["affine"][s].displacement)
                          .norm());
    std::cout << "  first promotion in step " << first_promotion
              << "; before it auto - affine " << before << " m" << std::endl;
    record("automatic_kinematics.drop.first_promotion", first_promotion);
    record("automatic_kinematics.drop.before", before, 2);
    check(before <= 1e-14, "auto follows the affine run until the impact");

    // The rebound: auto against meshed, within 1 % of the scene (4 m).
    const double off = (boulder["auto"].back().displacement -
                        boulder["meshed"].back().displacement)
                         .norm();
    std::cout << "  boulder at 0.2 s, auto - meshed: " << off << " m"
              << std::endl;
    record("automatic_kinematics.drop.off_meshed", off, 2);
    check(off <= 0.01 * 4., "auto rebounds as the meshed boulder");
  }

  /** Case 3: prm/wall_impact.prm, auto against all meshed. */
  void
  check_wall_impact()
  {
    std::cout << "3. wall impact" << std::endl;
    std::string text = read_example("wall_impact");
    text.replace(text.find("set Interval"),
                 std::string("set Interval").size(),
                 "set Write vtu = false\n  set Interval");
    std::vector<Point<2>> centroid[2];
    double                seconds[2];
    unsigned int          most_meshed = 0, promotions = 0, demotions = 0;
    double                farthest   = 0;
    double                scene_size = 0;
    for (const bool automatic : {false, true})
      {
        std::string       scene = text;
        const std::string entry = "set Kinematics      = auto";
        check(scene.find(entry) != std::string::npos, "prm: " + entry);
        if (!automatic)
          scene.replace(scene.find(entry),
                        entry.size(),
                        "set Kinematics = meshed");
        ndda::Simulator<2> simulator(read_parameters(scene, "wall_impact"));
        simulator.setup();
        const auto box = simulator.get_mesh().bounding_box();
        scene_size =
          std::max(box.second[0] - box.first[0], box.second[1] - box.first[1]);
        const auto start   = std::chrono::steady_clock::now();
        const auto initial = block_centroids(simulator);
        // Where the boulder strikes the wall's top.
        const Point<2> impact(8.1, 6.0);
        while (simulator.get_time() < 0.3 - 1e-12)
          {
            simulator.do_time_step();
            if (!automatic)
              continue;
            const auto meshed = simulator.get_discretization().meshed_blocks();
            most_meshed       = std::max<unsigned int>(
              most_meshed, std::count(meshed.begin(), meshed.end(), true));
            for (unsigned int b = 0; b < meshed.size(); ++b)
              if (meshed[b])
                farthest = std::max(farthest, initial[b].distance(impact));
          }
        seconds[automatic] = std::chrono::duration<double>(
                               std::chrono::steady_clock::now() - start)
                               .count();
        centroid[automatic] = block_centroids(simulator);
        if (automatic)
          {
            promotions = simulator.get_automatic_kinematics().n_promotions();
            demotions  = simulator.get_automatic_kinematics().n_demotions();
          }
      }
    double off = 0;
    for (unsigned int b = 0; b < centroid[0].size(); ++b)
      off = std::max(off, centroid[0][b].distance(centroid[1][b]));
    std::cout << "  blocks " << centroid[0].size() << ", scene size "
              << scene_size << " m; largest centroid difference " << off
              << " m (" << 100. * off / scene_size << " %)\n"
              << "  promotions " << promotions << ", demotions " << demotions
              << ", most meshed at once " << most_meshed
              << ", farthest meshed block " << farthest
              << " m from the impact\n"
              << "  wall time meshed " << seconds[0] << " s, auto "
              << seconds[1] << " s (ratio " << seconds[1] / seconds[0] << ")"
              << std::endl;
    record("automatic_kinematics.wall.off", off, 2);
    record("automatic_kinematics.wall.off_percent", 100. * off / scene_size, 2);
    record("automatic_kinematics.wall.promotions", promotions);
    record("automatic_kinematics.wall.demotions", demotions);
    record("automatic_kinematics.wall.most_meshed", most_meshed);
    record("automatic_kinematics.wall.farthest", farthest, 2);
    record("automatic_kinematics.wall.seconds_meshed", seconds[0], 2);
    record("automatic_kinematics.wall.seconds_auto", seconds[1], 2);
    record("automatic_kinematics.wall.cost_ratio", seconds[1] / seconds[0], 2);
    check(off <= 0.01 * scene_size, "auto within 1 % of the meshed run");
    check(promotions >= 1 && most_meshed <= centroid[0].size() / 10,
          "the impact meshes a few blocks, not the wall");
    check(farthest <= 2., "only blocks near the impact are meshed");
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const auto                       start = std::chrono::steady_clock::now();
  check_indicator();
  check_drop();
  check_wall_impact();
  report_wall_time("automatic_kinematics", start);
  std::cout << "OK" << std::endl;
}
