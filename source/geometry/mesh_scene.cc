// SPDX-License-Identifier: GPL-3.0-or-later
//
// From scene geometry to a BlockMesh, in three steps, each in its own
// translation unit of source/geometry/:
//  - scene_validation.cc: validation of the polygons, cracks and joints, and
//    of the scene's settings, before anything is cut or meshed;
//  - block_cutting.cc: block cutting of regions by joints, and of explicit
//    blocks by their cracks (CGAL Arrangement_2);
//  - block_meshing.cc: meshing of every block on its own (CGAL constrained
//    Delaunay mesher) and splitting of its vertices along its cracks.
// This file puts the blocks together into one mesh. All CGAL code of ndda
// lives in these units; they share the private header cgal_kernels.h (the
// kernels, and why there are two), and nothing of CGAL leaks into a public
// header.

#include <deal.II/base/numbers.h>

#include <ndda/geometry/block_mesh.h>

#include <cmath>
#include <iomanip>
#include <sstream>
#include <utility>
#include <vector>

#include "cgal_kernels.h"

namespace ndda
{
  namespace geometry
  {
    namespace
    {
      /**
       * Append the mesh of one block, cut and meshed from @p domain, to the
       * scene, with the vertex numbers shifted behind the scene's: blocks
       * never share vertices.
       */
      void
      append_block(const BlockMesh        &block,
                   const unsigned int      block_index,
                   const internal::Domain &domain,
                   BlockMesh              &scene)
      {
        const unsigned int offset = scene.vertices.size();
        scene.vertices.insert(scene.vertices.end(),
                              block.vertices.begin(),
                              block.vertices.end());
        for (const auto &t : block.triangles)
          scene.triangles.push_back(
            {{t[0] + offset, t[1] + offset, t[2] + offset}});
        scene.cell_block.insert(scene.cell_block.end(),
                                block.triangles.size(),
                                block_index);
        scene.cell_material.insert(scene.cell_material.end(),
                                   block.triangles.size(),
                                   domain.material_id);
        for (const auto &e : block.crack_edges)
          scene.crack_edges.push_back({{e[0] + offset, e[1] + offset}});
        scene.block_names.push_back(domain.name);
      }


      /**
       * Refuse grading settings a user can get wrong: a growth rate not
       * above 1, a size that is negative or not finite, a refinement
       * point that is not finite or has no positive size.
       */
      void
      check_grading(const MeshGrading &grading)
      {
        AssertThrow(
          std::isfinite(grading.growth_rate) && grading.growth_rate > 1.,
          dealii::ExcMessage("Geometry/Mesh grading/Growth rate: got " +
                             std::to_string(grading.growth_rate) +
                             ". Give a ratio of neighbouring triangle sizes "
                             "above 1, for example 1.3."));
        for (const auto &[size, entry] :
             {std::make_pair(grading.hole_size, "Hole mesh size"),
              std::make_pair(grading.crack_tip_size, "Crack tip mesh size"),
              std::make_pair(grading.notch_size, "Notch mesh size"),
              std::make_pair(grading.loaded_point_size,
                             "Loaded point mesh size")})
          AssertThrow(std::isfinite(size) && size >= 0.,
                      dealii::ExcMessage(
                        std::string("Geometry/Mesh grading/") + entry +
                        ": got " + std::to_string(size) +
                        ". Give a length (m) > 0, or 0 for no refinement "
                        "there."));
        for (const auto &[p, size] : grading.refinement_points)
          AssertThrow(std::isfinite(p[0]) && std::isfinite(p[1]) &&
                        std::isfinite(size) && size > 0.,
                      dealii::ExcMessage(
                        "Geometry/Mesh grading/Refinement points: the "
                        "point " +
                        internal::format_point(p[0], p[1]) + " with size " +
                        std::to_string(size) +
                        " is not finite or its size is not positive. Give "
                        "'x, y, size; ...' with sizes > 0 (m)."));
      }


      /**
       * Refuse, before meshing, a graded scene whose size fields ask for
       * far more cells than Geometry/Maximum number of cells (the uniform
       * part is checked with the polygons, in validate_scene()). The count
       * is internal::expected_cells(), an estimate: it is checked against
       * twice the limit, so that only sizes far too small are refused.
       */
      void
      check_graded_cell_count(const SceneGeometry                 &geometry,
                              const std::vector<internal::Domain> &domains,
                              const std::vector<SizeField>        &fields)
      {
        double       total = 0., largest = -1.;
        unsigned int largest_block = 0;
        for (unsigned int b = 0; b < domains.size(); ++b)
          {
            const double n = internal::expected_cells(domains[b], fields[b]);
            total += n;
            if (n > largest)
              {
                largest       = n;
                largest_block = b;
              }
          }
        if (total <= 2. * geometry.max_cells)
          return;
        std::ostringstream message;
        message << std::setprecision(3)
                << "Geometry/Mesh grading: the graded meshes need about "
                << total << " cells, far more than Geometry/Maximum number of "
                << "cells = " << geometry.max_cells << " (block '"
                << domains[largest_block].name << "' alone about " << largest
                << "). Give larger feature sizes or a larger growth rate, or "
                   "raise the limit if the machine holds such a scene.";
        AssertThrow(false, dealii::ExcMessage(message.str()));
      }
    } // namespace



    BlockMesh
    mesh_scene(const SceneGeometry &input)
    {
      // Corners computed by trigonometry land within a rounding error of
      // each other: they become one point before anything is checked.
      check_grading(input.grading);
      const SceneGeometry geometry = internal::snap_corners(input);
      // Validate everything before meshing anything, so that the user sees
      // the input errors at once.
      const std::vector<internal::Polygon> polygons =
        internal::validate_scene(geometry);
      const double sine =
        std::sin(geometry.min_angle * dealii::numbers::PI / 180.);
      const double shape_bound = sine * sine;

      std::vector<internal::Domain> domains;
      for (std::size_t b = 0; b < geometry.blocks.size(); ++b)
        domains.push_back(
          internal::block_domain(polygons[b], geometry.blocks[b]));
      for (std::size_t r = 0; r < geometry.regions.size(); ++r)
        for (auto &domain :
             internal::region_domains(polygons[geometry.blocks.size() + r],
                                      geometry.regions[r]))
          domains.push_back(std::move(domain));

      std::vector<SizeField> size_fields;
      for (const auto &domain : domains)
        size_fields.push_back(
          internal::size_field_of(domain, geometry.grading));
      if (geometry.grading.is_active())
        check_graded_cell_count(geometry, domains, size_fields);

      // Every block is meshed on its own and gets its own range of vertex
      // numbers: blocks never share vertices.
      BlockMesh scene;
      for (unsigned int b = 0; b < domains.size(); ++b)
        {
          const BlockMesh block =
            internal::mesh_domain(domains[b],
                                  geometry.required_vertices,
                                  shape_bound,
                                  size_fields[b]);
          append_block(block, b, domains[b], scene);
        }
      return scene;
    }
  } // namespace geometry
} // namespace ndda
