// SPDX-License-Identifier: GPL-3.0-or-later
//
// Graded meshes (Geometry/Mesh grading, geometry/size_field.h). For each
// feature kind, a block is meshed with and without grading, and the test
// checks that
//  - every triangle's longest edge is within the size field at its
//    centroid (the mesher got the field), and the minimum angle holds;
//  - the triangles at the feature are as small as the feature's size, the
//    ones far from it as large as the block's mesh size: the mesh is fine
//    only where it was asked to be;
//  - the graded mesh has far fewer cells than a uniform mesh of the
//    feature's size, and SizeField::extra_cells() estimates its count
//    within a factor 2.
// Cases: a square with a round hole (hole size), a square with an interior
// crack (crack tip size), an L-shaped block (notch size), and the
// Loaded point size through a .prm scene with a point load and a fixed
// point, and a refinement point. Without grading the mesh is unchanged:
// geometry_cutting pins the uniform meshes.

#include <deal.II/base/exceptions.h>

#include <ndda/geometry/block_mesh.h>
#include <ndda/geometry/size_field.h>
#include <ndda/simulator.h>

#include <algorithm>
#include <cmath>

#include "tests.h"

using namespace ndda_tests;
using namespace ndda::geometry;

namespace
{
  struct MeshFigures
  {
    unsigned int n_cells = 0;
    /// Largest longest edge over the field at the centroid.
    double worst_ratio = 0;
    /// Smallest angle of any triangle (degrees).
    double min_angle = 180;
    /// Largest longest edge among the triangles within @p radius of the
    /// feature, and smallest longest edge among those farther than
    /// @p far from it.
    double largest_near = 0, smallest_far = 1e30;
  };

  double
  longest_edge(const BlockMesh &mesh, const std::array<unsigned int, 3> &t)
  {
    double h = 0;
    for (unsigned int i = 0; i < 3; ++i)
      h = std::max(h,
                   mesh.vertices[t[i]].distance(mesh.vertices[t[(i + 1) % 3]]));
    return h;
  }

  double
  smallest_angle(const BlockMesh &mesh, const std::array<unsigned int, 3> &t)
  {
    double angle = 180;
    for (unsigned int i = 0; i < 3; ++i)
      {
        const auto u = mesh.vertices[t[(i + 1) % 3]] - mesh.vertices[t[i]];
        const auto v = mesh.vertices[t[(i + 2) % 3]] - mesh.vertices[t[i]];
        angle        = std::min(angle,
                         std::acos(u * v / (u.norm() * v.norm())) * 180 / M_PI);
      }
    return angle;
  }

  /**
   * Mesh @p geometry and measure it against @p field; @p distance is the
   * distance of a point to the feature.
   */
  template <typename Distance>
  MeshFigures
  measure(const SceneGeometry &geometry,
          const SizeField     &field,
          const Distance      &distance,
          const double         near,
          const double         far)
  {
    const BlockMesh mesh = mesh_scene(geometry);
    MeshFigures     figures;
    figures.n_cells = mesh.triangles.size();
    for (const auto &t : mesh.triangles)
      {
        const Point<2> centroid(
          (mesh.vertices[t[0]][0] + mesh.vertices[t[1]][0] +
           mesh.vertices[t[2]][0]) /
            3,
          (mesh.vertices[t[0]][1] + mesh.vertices[t[1]][1] +
           mesh.vertices[t[2]][1]) /
            3);
        const double h = longest_edge(mesh, t);
        figures.worst_ratio =
          std::max(figures.worst_ratio, h / field(centroid));
        figures.min_angle =
          std::min(figures.min_angle, smallest_angle(mesh, t));
        const double d = distance(centroid);
        if (d < near)
          figures.largest_near = std::max(figures.largest_near, h);
        if (d > far)
          figures.smallest_far = std::min(figures.smallest_far, h);
      }
    return figures;
  }

  /**
   * Mesh a block graded at one feature of size @p h_feature, compare with
   * the same block meshed uniformly at @p h_feature, and check the
   * figures the header names.
   */
  template <typename Distance>
  void
  check_case(const std::string &name,
             SceneGeometry      geometry,
             const SizeField   &field,
             const double       h_feature,
             const Distance    &distance)
  {
    const double H = geometry.blocks[0].mesh_size;
    const double g = geometry.grading.growth_rate;
    // Within one feature size the bound is at most 2 h_f (g <= 2); one
    // mesh size beyond the reach (H - h_f)/(g - 1) every triangle has the
    // bound H.
    const MeshFigures graded = measure(
      geometry, field, distance, h_feature, (H - h_feature) / (g - 1) + H);
    geometry.grading             = MeshGrading();
    const unsigned int n_coarse  = mesh_scene(geometry).triangles.size();
    geometry.blocks[0].mesh_size = h_feature;
    const unsigned int n_fine    = mesh_scene(geometry).triangles.size();
    const double       estimate  = n_coarse + field.extra_cells();

    std::cout << name << ": graded " << graded.n_cells << " cells (uniform at "
              << "the block's size " << n_coarse << ", at the feature's size "
              << n_fine << ", estimate " << estimate << "); longest edge / "
              << "field at most " << graded.worst_ratio << "; smallest angle "
              << graded.min_angle << " degrees; at the feature the longest "
              << "edge is at most " << graded.largest_near / h_feature
              << " h_f, far from it at least " << graded.smallest_far / H
              << " H" << std::endl;
    record("geometry_grading." + name + ".cells", graded.n_cells);
    record("geometry_grading." + name + ".uniform_fine_cells", n_fine);
    check(graded.worst_ratio <= 1 + 1e-12,
          name + ": every triangle within the size field");
    check(graded.min_angle >= 30 - 1e-9, name + ": the minimum angle holds");
    check(graded.largest_near <= 2 * h_feature,
          name + ": the triangles at the feature have its size");
    check(graded.smallest_far >= H / 3,
          name + ": the triangles far from the feature are not refined");
    check(graded.n_cells * 4 < n_fine,
          name + ": at least 4 times fewer cells than the uniform fine mesh");
    check(estimate > graded.n_cells / 2. && estimate < 2. * graded.n_cells,
          name + ": the cell estimate within a factor 2");
  }

  std::vector<Point<2>>
  square(const double size)
  {
    return {Point<2>(0, 0),
            Point<2>(size, 0),
            Point<2>(size, size),
            Point<2>(0, size)};
  }

} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::cout << std::setprecision(4);
  const double H = 0.1, g = 1.25;

  // A hole: a 128-gon of radius 0.1 in the middle of a unit square.
  {
    SceneGeometry    geometry;
    BlockDescription block;
    block.name      = "plate";
    block.outer     = square(1);
    block.mesh_size = H;
    std::vector<Point<2>> hole;
    for (unsigned int k = 0; k < 128; ++k)
      hole.emplace_back(0.5 + 0.1 * std::cos(2 * M_PI * k / 128),
                        0.5 + 0.1 * std::sin(2 * M_PI * k / 128));
    block.holes = {hole};
    geometry.blocks.push_back(block);
    geometry.grading.growth_rate = g;
    geometry.grading.hole_size   = 0.005;
    SizeField field(H, g);
    for (unsigned int k = 0; k < 128; ++k)
      field.add_segment(hole[k], hole[(k + 1) % 128], 0.005);
    check_case("hole", geometry, field, 0.005, [](const Point<2> &x) {
      return x.distance(Point<2>(0.5, 0.5)) - 0.1;
    });
  }

  // A crack from (0.3, 0.5) to (0.7, 0.5): its two tips.
  {
    SceneGeometry    geometry;
    BlockDescription block;
    block.name      = "plate";
    block.outer     = square(1);
    block.mesh_size = H;
    block.cracks    = {{Point<2>(0.3, 0.5), Point<2>(0.7, 0.5)}};
    geometry.blocks.push_back(block);
    geometry.grading.growth_rate    = g;
    geometry.grading.crack_tip_size = 0.004;
    SizeField field(H, g);
    field.add_point(Point<2>(0.3, 0.5), 0.004);
    field.add_point(Point<2>(0.7, 0.5), 0.004);
    check_case("crack_tip", geometry, field, 0.004, [](const Point<2> &x) {
      return std::min(x.distance(Point<2>(0.3, 0.5)),
                      x.distance(Point<2>(0.7, 0.5)));
    });
  }

  // An L: the re-entrant corner at (0.5, 0.5) is the only notch; the
  // other five corners are convex and keep the block's size.
  {
    SceneGeometry    geometry;
    BlockDescription block;
    block.name      = "L";
    block.outer     = {Point<2>(0, 0),
                       Point<2>(1, 0),
                       Point<2>(1, 0.5),
                       Point<2>(0.5, 0.5),
                       Point<2>(0.5, 1),
                       Point<2>(0, 1)};
    block.mesh_size = H;
    geometry.blocks.push_back(block);
    geometry.grading.growth_rate = g;
    geometry.grading.notch_size  = 0.004;
    SizeField field(H, g);
    field.add_point(Point<2>(0.5, 0.5), 0.004);
    check_case("notch", geometry, field, 0.004, [](const Point<2> &x) {
      return x.distance(Point<2>(0.5, 0.5));
    });
  }

  // A refinement point off every feature, at (0.2, 0.7).
  {
    SceneGeometry    geometry;
    BlockDescription block;
    block.name      = "plate";
    block.outer     = square(1);
    block.mesh_size = H;
    geometry.blocks.push_back(block);
    geometry.grading.growth_rate       = g;
    geometry.grading.refinement_points = {{Point<2>(0.2, 0.7), 0.005}};
    SizeField field(H, g);
    field.add_point(Point<2>(0.2, 0.7), 0.005);
    check_case(
      "refinement_point", geometry, field, 0.005, [](const Point<2> &x) {
        return x.distance(Point<2>(0.2, 0.7));
      });
    // A growth rate of 1 would never coarsen: refused, naming the entry.
    {
      SceneGeometry flat       = geometry;
      flat.grading.growth_rate = 1.;
      bool refused             = false;
      try
        {
          mesh_scene(flat);
        }
      catch (const dealii::ExceptionBase &e)
        {
          refused = std::string(e.what()).find(
                      "Geometry/Mesh grading/Growth rate") != std::string::npos;
        }
      check(refused, "a growth rate of 1 is refused, naming the entry");
    }
    // A hole size in a block without holes changes nothing.
    const BlockMesh without    = mesh_scene(geometry);
    geometry.grading.hole_size = 0.001;
    const BlockMesh with       = mesh_scene(geometry);
    check(with.vertices == without.vertices,
          "a hole size without holes changes nothing");
  }

  // Through a .prm scene: a point load at the top's middle and a fixed
  // point at the bottom's middle are loaded points; the hole size of a
  // scene without holes changes nothing.
  {
    const auto scene = [](const double loaded_point_size) {
      std::ostringstream text;
      text << R"(
subsection Control
  set Analysis type = quasi-static
end
subsection Materials
  set Names = rock
  subsection rock
    set Young's modulus = 1e9
  end
end
subsection Geometry
  set Blocks = plate
  subsection plate
    set Outer boundary = 0, 0; 1, 0; 1, 1; 0, 1
    set Material = rock
    set Mesh size = 0.1
  end
  subsection Mesh grading
    set Loaded point mesh size = )"
           << loaded_point_size << R"(
    set Hole mesh size = 0.01
  end
end
subsection Loads
  set Point loads = top
  subsection top
    set Point = 0.5, 1
    set Force = 0; -1e3
  end
end
subsection Boundary conditions
  set Names = pin
  subsection pin
    set Type = fixed
    set Points = 0.5, 0; 0.2, 0
  end
end
subsection Output
  set Write vtu = false
end
)";
      return read_parameters(text.str(), "geometry_grading");
    };
    const auto largest_edge_at = [](const ndda::Simulator<2> &simulator,
                                    const Point<2>           &p) {
      double largest = 0;
      for (const auto &cell : simulator.get_dof_handler()
                                .get_triangulation()
                                .active_cell_iterators())
        for (unsigned int v = 0; v < 3; ++v)
          if (cell->vertex(v).distance(p) < 1e-12)
            for (unsigned int l = 0; l < 3; ++l)
              largest = std::max(largest, cell->line(l)->diameter());
      return largest;
    };
    ndda::Simulator<2> uniform(scene(0));
    uniform.setup();
    ndda::Simulator<2> graded(scene(0.004));
    graded.setup();
    const auto n = [](const ndda::Simulator<2> &s) {
      return s.get_dof_handler().get_triangulation().n_active_cells();
    };
    const double at_load = largest_edge_at(graded, Point<2>(0.5, 1));
    const double at_pin  = largest_edge_at(graded, Point<2>(0.5, 0));
    std::cout << "loaded points: " << n(uniform) << " cells uniform, "
              << n(graded) << " graded; longest edge at the load " << at_load
              << " m, at the fixed point " << at_pin << " m" << std::endl;
    check(at_load <= 0.008 && at_pin <= 0.008,
          "the cells at the loaded points have the loaded point size");
    check(largest_edge_at(uniform, Point<2>(0.5, 1)) > 0.03,
          "without a loaded point size the cells there are coarse");
  }
  return 0;
}
