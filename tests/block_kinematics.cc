// SPDX-License-Identifier: GPL-3.0-or-later
//
// Rigid and affine blocks (issue 15; doc/design.md, "Block kinematics"):
// the constraints that tie a block's nodes to its unknowns, together with
// the exact constraints of its nodes, in cases whose answer is known.
//
//  1. Affine patch test: a 1 m square on rollers (bottom: vertical,
//     left: horizontal) under a 1 MPa pressure on its top, quasi-static, P1 and
//     P2: the stress must be uniaxial -1 MPa in every cell and the top
//     corner's displacement that of the meshed block (exact for a
//     constant stress), to round-off.
//  2. A rigid block driven by a prescribed velocity on its left edge only,
//     0.1 m/s for 0.1 s, no gravity: every node moves by 0.01 m exactly
//     (the velocity fixes three of the block's unknowns through two
//     nodes' rows), and stays unstressed.
//  3. A rigid block on a roller (its bottom edge free to slide along x),
//     under gravity and a horizontal force F: it slides with a = F / m
//     and does not sink.
//  4. A pinned rigid bar with penalty constraints instead of exact ones:
//     it still swings about its pin (its far top corner, 1 m from the pin,
//     reaches 1 m below it, to 1 mm), and stays rigid.
//  5. A rigid bar whose top left corner slides on a roller along x, under
//     gravity: a block with a roller keeps the global frame, so its lines
//     are rebuilt whenever it turns; it must stay rigid and its corner on
//     the roller's line.
//  6. The pre-cracked Brazilian disc with rigid plates: only the disc
//     cracks, and the plates stay rigid after the cracks (their nodes'
//     displacements are one rigid motion).

#include <algorithm>
#include <cmath>
#include <map>

#include "tests.h"

using namespace ndda_tests;
using namespace dealii;

namespace
{
  const std::string square = R"(
subsection Control
  set Analysis type   = {analysis}
  set Time integrator = {integrator}
  set Time step       = {dt}
  set End time        = {end}
  set Element degree  = {degree}
  set Maximum displacement ratio = 0.5
  set Kinematics      = {model}
  set Constraint method = {method}
end
subsection Contact
  set Enable = false
end
subsection Materials
  set Names = rock
  set Plane condition = plane stress
  subsection rock
    set Density = 2000
    set Young's modulus = 1e9
    set Poisson's ratio = 0.25
  end
end
subsection Geometry
  set Blocks = block
  subsection block
    set Outer boundary = {outer}
    set Material = rock
    set Mesh size = 0.25
  end
end
subsection Loads
  set Gravity = 0; {g}
{loads}
end
subsection Boundary conditions
{conditions}
end
subsection Output
  set Write vtu = false
  set Measure points = 1, 1
end
)";

  /** The subsections of the loads and constraints the cases use. */
  const std::map<std::string, std::string> snippets = {{"top", R"(
  subsection top
    set Segment = 0, 1, 1, 1
    set Type = pressure
    set Value = 1e6
  end)"},
                                                       {"push", R"(
  subsection push
    set Point = 1, 0.5
    set Force = 1e5; 0
  end)"},
                                                       {"bottom", R"(
  subsection bottom
    set Type = roller
    set Segments = 0, 0, 1, 0
  end)"},
                                                       {"left", R"(
  subsection left
    set Type = roller
    set Roller angle = 90
    set Segments = 0, 0, 0, 1
  end)"},
                                                       {"drive", R"(
  subsection drive
    set Type = velocity
    set Value = 0.1; 0
    set Segments = 0, 0, 0, 1
  end)"},
                                                       {"slide", R"(
  subsection slide
    set Type = roller
    set Points = 0, 1
  end)"},
                                                       {"pin", R"(
  subsection pin
    set Type = fixed
    set Points = 0, 1
  end)"}};

  /** The scene with @p values, its loads and constraints by name
   * (line_loads, point_loads, conditions: comma separated). */
  std::string
  scene(std::map<std::string, std::string> values)
  {
    std::string loads = "  set Line loads = " + values["line_loads"] +
                        "\n  set Point loads = " + values["point_loads"];
    std::string conditions = "  set Names = " + values["conditions"];
    for (const auto &[key, text] :
         {std::pair<std::string, std::string *>("line_loads", &loads),
          {"point_loads", &loads},
          {"conditions", &conditions}})
      for (const auto &name : Utilities::split_string_list(values[key]))
        *text += snippets.at(name);
    values["loads"]      = loads;
    values["conditions"] = conditions;
    return substitute(square, values);
  }

  std::map<std::string, std::string>
  defaults()
  {
    return {{"analysis", "dynamic"},
            {"integrator", "Newmark"},
            {"dt", "1e-3"},
            {"end", "0.1"},
            {"degree", "1"},
            {"model", "rigid"},
            {"method", "exact"},
            {"outer", "0, 0; 1, 0; 1, 1; 0, 1"},
            {"g", "0"},
            {"line_loads", ""},
            {"point_loads", ""},
            {"conditions", ""}};
  }

  std::map<std::string, std::string>
  with(std::map<std::string, std::string>                      values,
       const std::vector<std::pair<std::string, std::string>> &changes)
  {
    for (const auto &[key, value] : changes)
      values[key] = value;
    return values;
  }

  /** The largest distance of the nodal displacements of @p simulator
   * from one rigid motion (the least-squares fit over all vertices). */
  double
  off_rigid(const ndda::Simulator<2> &simulator, const unsigned int block)
  {
    const auto &mesh = simulator.get_mesh();
    const auto &tria = mesh.get_triangulation();
    const auto &u    = simulator.get_displacement();
    // Vertices of the block with their displacements.
    std::vector<Point<2>>                x;
    std::vector<Tensor<1, 2>>            d;
    std::vector<bool>                    seen(tria.n_vertices(), false);
    std::vector<types::global_dof_index> dofs;
    for (const auto &cell : simulator.get_dof_handler().active_cell_iterators())
      {
        if (mesh.block_of_cell(cell->active_cell_index()) != block)
          continue;
        dofs.resize(cell->get_fe().n_dofs_per_cell());
        cell->get_dof_indices(dofs);
        for (unsigned int v = 0; v < 3; ++v)
          if (!seen[cell->vertex_index(v)])
            {
              seen[cell->vertex_index(v)] = true;
              // P1 and P2 list the vertex dofs first, x then y.
              x.push_back(cell->vertex(v));
              d.push_back(Tensor<1, 2>({u[dofs[2 * v]], u[dofs[2 * v + 1]]}));
            }
      }
    // A rigid motion maps x0 = x - d to x: fit centre and angle.
    Point<2> c0, c1;
    for (unsigned int i = 0; i < x.size(); ++i)
      {
        c0 += (x[i] - d[i]) / double(x.size());
        c1 += x[i] / double(x.size());
      }
    double s = 0, c = 0;
    for (unsigned int i = 0; i < x.size(); ++i)
      {
        const Tensor<1, 2> a = x[i] - d[i] - c0, b = x[i] - c1;
        c += a * b;
        s += a[0] * b[1] - a[1] * b[0];
      }
    const double angle = std::atan2(s, c);
    double       worst = 0;
    for (unsigned int i = 0; i < x.size(); ++i)
      {
        const Tensor<1, 2> a = x[i] - d[i] - c0;
        const Point<2>     fit(c1[0] + std::cos(angle) * a[0] -
                             std::sin(angle) * a[1],
                           c1[1] + std::sin(angle) * a[0] +
                             std::cos(angle) * a[1]);
        worst = std::max(worst, fit.distance(x[i]));
      }
    return worst;
  }

  void
  run_to_end(ndda::Simulator<2> &simulator)
  {
    simulator.setup();
    const double end = simulator.get_parameters().control.end_time;
    while (simulator.get_time() < end - 1e-12)
      simulator.do_time_step();
  }
} // namespace

int
main(int argc, char **argv)
{
  using namespace dealii;
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  // 1. Affine patch test against the meshed block.
  for (const std::string degree : {"1", "2"})
    {
      Tensor<1, 2> corner[2];
      double       stress_error = 0;
      for (const std::string model : {"meshed", "affine"})
        {
          ndda::Simulator<2> simulator(
            read_parameters(scene(with(defaults(),
                                       {{"analysis", "quasi-static"},
                                        {"end", "1e-3"},
                                        {"degree", degree},
                                        {"model", model},
                                        {"line_loads", "top"},
                                        {"conditions", "bottom, left"}})),
                            "affine_patch"));
          run_to_end(simulator);
          corner[model == "affine"] =
            simulator.get_measure_histories()[0].back().displacement;
          for (unsigned int c = 0;
               c < simulator.get_mesh().get_triangulation().n_active_cells();
               ++c)
            for (const auto &sigma : simulator.get_cell_stress(c))
              stress_error = std::max({stress_error,
                                       std::abs(sigma[0][0]),
                                       std::abs(sigma[1][1] + 1e6),
                                       std::abs(sigma[0][1])});
        }
      const double difference =
        (corner[1] - corner[0]).norm() / corner[0].norm();
      std::cout << "affine patch test, P" << degree << ": top corner "
                << corner[1] << " m (meshed " << corner[0]
                << "), relative difference " << difference
                << ", stress off -1 MPa uniaxial by " << stress_error << " Pa"
                << std::endl;
      record("block_kinematics.patch.P" + degree + ".difference",
             difference,
             2);
      record("block_kinematics.patch.P" + degree + ".stress", stress_error, 2);
      check(difference < 1e-9, "affine block: the meshed block's displacement");
      check(stress_error < 1e-3, "affine block: uniaxial stress");
    }

  // 2. A rigid block driven on one edge.
  {
    ndda::Simulator<2> simulator(
      read_parameters(scene(with(defaults(), {{"conditions", "drive"}})),
                      "rigid_driven"));
    run_to_end(simulator);
    const auto &u     = simulator.get_displacement();
    double      worst = 0;
    double      sigma = 0;
    const auto &dofs  = simulator.get_dof_handler();
    for (unsigned int i = 0; i < dofs.n_dofs(); i += 2)
      worst = std::max({worst, std::abs(u[i] - 0.01), std::abs(u[i + 1])});
    for (unsigned int c = 0;
         c < simulator.get_mesh().get_triangulation().n_active_cells();
         ++c)
      sigma = std::max(sigma, simulator.mean_cell_stress(c).norm());
    std::cout << "rigid block driven at 0.1 m/s on its left edge for 0.1 s: "
                 "nodes off 0.01 m by at most "
              << worst << " m, largest stress " << sigma << " Pa" << std::endl;
    record("block_kinematics.driven", worst, 2);
    check(worst < 1e-12, "driven rigid block moves with its edge");
    check(sigma < 1, "driven rigid block stays unstressed");
  }

  // 3. A rigid block on a roller, pushed sideways.
  for (const std::string integrator : {"Newmark", "DDA"})
    {
      ndda::Simulator<2> simulator(
        read_parameters(scene(with(defaults(),
                                   {{"integrator", integrator},
                                    {"g", "-9.81"},
                                    {"point_loads", "push"},
                                    {"conditions", "bottom"}})),
                        "rigid_roller"));
      run_to_end(simulator);
      // m = 2000 kg (1 m^2, thickness 1 m): x = F t^2 / (2 m).
      const double expected = 0.5 * 1e5 / 2000 * 0.1 * 0.1;
      const auto  &u = simulator.get_measure_histories()[0].back().displacement;
      const double error = u[0] / expected - 1;
      std::cout << "rigid block on a roller, " << integrator << ": slid "
                << u[0] << " m (F t^2 / 2 m = " << expected << " m), error "
                << 100 * error << " %, vertical " << u[1] << " m, off rigid "
                << off_rigid(simulator, 0) << " m" << std::endl;
      record("block_kinematics.roller." + integrator, 100 * error, 2);
      check(std::abs(error) < 1e-9, "rigid block on a roller: a = F / m");
      check(std::abs(u[1]) < 1e-12, "rigid block on a roller: no sinking");
    }

  // 4. A pinned rigid bar with penalty constraints.
  {
    ndda::Simulator<2> simulator(
      read_parameters(scene(with(defaults(),
                                 {{"method", "penalty"},
                                  {"g", "-9.81"},
                                  {"end", "1"},
                                  {"outer", "0, 0.9; 1, 0.9; 1, 1; 0, 1"},
                                  {"conditions", "pin"}})),
                      "rigid_penalty_pin"));
    simulator.setup();
    double lowest = 1;
    while (simulator.get_time() < 1 - 1e-12)
      {
        simulator.do_time_step();
        lowest = std::min(
          lowest,
          1 + simulator.get_measure_histories()[0].back().displacement[1]);
      }
    // The measure point (1, 1) is 1 m from the pin: at the bottom of the
    // swing it hangs 1 m below it.
    std::cout << "rigid bar on a penalty pin: lowest point of its far top "
                 "corner "
              << lowest << " m (1 m below the pin: 0 m), off rigid "
              << off_rigid(simulator, 0) << " m" << std::endl;
    record("block_kinematics.penalty_lowest", lowest, 2);
    check(std::abs(lowest) < 1e-3, "penalty pin holds the rigid bar");
    check(off_rigid(simulator, 0) < 1e-9, "rigid bar stays rigid");
  }

  // 5. A rigid bar on a one-point roller.
  {
    ndda::Simulator<2> simulator(
      read_parameters(scene(with(defaults(),
                                 {{"g", "-9.81"},
                                  {"end", "0.5"},
                                  {"outer", "0, 0.9; 1, 0.9; 1, 1; 0, 1"},
                                  {"conditions", "slide"}})),
                      "rigid_roller_point"));
    run_to_end(simulator);
    // The vertex that started at (0, 1).
    const auto &vertices = simulator.get_mesh().get_block_mesh().vertices;
    const auto  u        = simulator.get_displacement();
    const auto &dof_map  = simulator.get_dof_handler();
    double      corner_y = 1;
    for (const auto &cell : dof_map.active_cell_iterators())
      for (unsigned int v = 0; v < 3; ++v)
        {
          std::vector<types::global_dof_index> dofs(
            cell->get_fe().n_dofs_per_cell());
          cell->get_dof_indices(dofs);
          const Point<2> start(cell->vertex(v)[0] - u[dofs[2 * v]],
                               cell->vertex(v)[1] - u[dofs[2 * v + 1]]);
          if (start.distance(Point<2>(0, 1)) < 1e-9)
            corner_y = cell->vertex(v)[1];
        }
    const auto &far = simulator.get_measure_histories()[0].back().displacement;
    std::cout << "rigid bar on a one-point roller: far corner moved by " << far
              << " m, roller corner at y = " << corner_y
              << " m (1 m), off rigid " << off_rigid(simulator, 0) << " m, "
              << vertices.size() << " vertices" << std::endl;
    record("block_kinematics.roller_point", off_rigid(simulator, 0), 2);
    check(far[1] < -0.1, "the bar falls and turns");
    check(std::abs(corner_y - 1) < 1e-9, "the roller corner stays on its line");
    check(off_rigid(simulator, 0) < 1e-9, "the bar stays rigid");
  }

  // 6. The pre-cracked Brazilian disc (prm/brazilian_disc_crack.prm) with
  // rigid plates, until its first crack events: cracks only in the disc,
  // the plates rigid before and after.
  {
    std::string text = read_example("brazilian_disc_crack");
    for (const std::string plate : {"subsection top\n", "subsection bottom\n"})
      text.replace(text.find(plate),
                   plate.size(),
                   plate + "    set Kinematics = rigid\n");
    ndda::Simulator<2> simulator(read_parameters(text, "rigid_plates"));
    simulator.setup();
    const unsigned int n_blocks = simulator.get_mesh().n_blocks();
    while (simulator.get_n_cracked_edges() < 20 &&
           simulator.get_time() < 3e-3 - 1e-12)
      simulator.do_time_step();
    const auto  &mesh        = simulator.get_mesh();
    const auto  &names       = mesh.get_block_names();
    unsigned int plate_faces = 0;
    for (const auto &e : mesh.get_block_mesh().crack_edges)
      for (unsigned int c = 0; c < mesh.get_triangulation().n_active_cells();
           ++c)
        {
          const auto &t = mesh.get_block_mesh().triangles[c];
          if (std::count(t.begin(), t.end(), e[0]) == 1 &&
              std::count(t.begin(), t.end(), e[1]) == 1 &&
              names[mesh.block_of_cell(c)].rfind("disc", 0) != 0)
            ++plate_faces;
        }
    double worst = 0;
    for (unsigned int b = 0; b < mesh.n_blocks(); ++b)
      if (names[b] == "top" || names[b] == "bottom")
        worst = std::max(worst, off_rigid(simulator, b));
    std::cout << "Brazilian disc with rigid plates: "
              << simulator.get_n_cracked_edges()
              << " cracked edges by t = " << simulator.get_time() * 1e3
              << " ms, " << mesh.n_blocks() << " blocks (" << n_blocks
              << " at the start), " << plate_faces
              << " crack faces in the plates, plates off rigid by " << worst
              << " m" << std::endl;
    record("block_kinematics.plates_cracked", simulator.get_n_cracked_edges());
    record("block_kinematics.plates_off_rigid", worst, 2);
    check(simulator.get_n_cracked_edges() > 0, "the disc cracks");
    check(plate_faces == 0, "rigid plates do not crack");
    check(worst < 1e-12, "plates stay rigid across the cracks");
  }
  std::cout << "OK" << std::endl;
}
