// SPDX-License-Identifier: GPL-3.0-or-later

#include <ndda/kinematics/automatic_kinematics.h>
#include <ndda/kinematics/block_kinematics.h>
#include <ndda/parameters/entries.h>
#include <ndda/scene/scene_parameters.h>

#include <filesystem>
#include <fstream>

namespace ndda
{
  namespace parameters
  {
    using namespace dealii;

    namespace
    {
      void
      declare_initial_state(ParameterHandler &prm)
      {
        prm.declare_entry("Initial stress",
                          "0, 0, 0",
                          Patterns::Anything(),
                          "Initial stress sigma_xx, sigma_yy, sigma_xy of all "
                          "cells of the block (Pa, tension positive).");
        prm.declare_entry(
          "Initial velocity",
          "0; 0",
          Patterns::Anything(),
          "Initial velocity v_x; v_y (m/s) as functions of x and y, e.g. "
          "'-2*y; 2*x' for a rotation about the origin at 2 rad/s.");
        prm.declare_entry(
          "Kinematics",
          "",
          Patterns::Anything(),
          "How the block moves, one of " +
            kinematics::BlockKinematicsRegistry::joined_names(", ") + " or " +
            kinematics::automatic_name +
            " (see Control/Kinematics). Empty: Control/Kinematics.");
      }

      InitialState
      parse_initial_state(ParameterHandler &prm, const std::string &where)
      {
        InitialState state;
        const auto   stress = parse_numbers(prm.get("Initial stress"),
                                          where + "/Initial stress",
                                          3);
        state.stress        = {{stress[0], stress[1], stress[2]}};
        state.velocity      = prm.get("Initial velocity");
        state.where         = where;
        check_function(state.velocity, 2, "x,y", where + "/Initial velocity");
        state.kinematics = Utilities::trim(prm.get("Kinematics"));
        if (!state.kinematics.empty())
          kinematics::check_name(state.kinematics, where + "/Kinematics");
        return state;
      }

      void
      declare_mesh_size(ParameterHandler &prm)
      {
        prm.declare_entry("Material",
                          "",
                          Patterns::Anything(),
                          "Name of the material of this block, one of "
                          "Materials/Names.");
        prm.declare_entry("Mesh size",
                          "0",
                          Patterns::Double(0.),
                          "Longest triangle edge (m). Zero: use 'Target "
                          "number of elements'.");
        prm.declare_entry("Target number of elements",
                          "0",
                          Patterns::Integer(0),
                          "Approximate number of triangles, used only if "
                          "'Mesh size' is zero.");
      }

      template <typename Description>
      void
      parse_mesh_size(ParameterHandler  &prm,
                      const std::string &where,
                      const Materials   &materials,
                      Description       &description)
      {
        description.material_id =
          materials.id(prm.get("Material"), where + "/Material");
        description.mesh_size = prm.get_double("Mesh size");
        description.target_n_cells =
          prm.get_integer("Target number of elements");
        AssertThrow(description.mesh_size > 0. ||
                      description.target_n_cells > 0,
                    ExcMessage(where +
                               ": neither 'Mesh size' nor 'Target number of "
                               "elements' is set. Set one of them, e.g. "
                               "'set Mesh size = 0.01'."));
      }
    } // namespace



    void
    Geometry::declare_parameters(ParameterHandler               &prm,
                                 const std::vector<std::string> &block_names,
                                 const std::vector<std::string> &region_names)
    {
      prm.enter_subsection("Geometry");
      prm.declare_entry("Blocks",
                        "",
                        Patterns::Anything(),
                        "Comma separated names of polygon blocks; each has "
                        "a subsection of that name.");
      prm.declare_entry("Regions",
                        "",
                        Patterns::Anything(),
                        "Comma separated names of rock regions cut into "
                        "blocks by joints; each has a subsection of that "
                        "name.");
      prm.declare_entry("Mesh file",
                        "",
                        Patterns::Anything(),
                        "A gmsh .msh file (relative to the .prm file) whose "
                        "physical surfaces are blocks. Used instead of "
                        "Blocks and Regions.");
      prm.declare_entry("Mesh file materials",
                        "",
                        Patterns::Anything(),
                        "Material of each physical surface of the mesh "
                        "file, 'tag: material, tag: material'. Empty: the "
                        "physical tag is the material id, an index into "
                        "Materials/Names (0 is the first).");
      prm.declare_entry(
        "Maximum number of cells",
        "1000000",
        Patterns::Integer(1),
        "Refuse, before meshing, a scene whose blocks need more cells than "
        "this: from each block's area and mesh size, the fewest cells a "
        "mesh with that longest edge can have (equilateral triangles, "
        "area sqrt(3)/4 h^2; the mesher makes 2 to 3 times as many), or "
        "its target number of elements. A meshed P1 cell takes about "
        "3 kB of memory in a run with the direct solver, 2 kB with "
        "CG-Jacobi (measured at 1e6 cells; P2 more); "
        "raise the limit for larger scenes on a machine that holds them.");
      prm.declare_entry(
        "Snapping tolerance",
        "1e-9",
        Patterns::Double(0., 1e-3),
        "Relative to the scene's size (the diagonal of the bounding box of "
        "all blocks and regions). Corners of different blocks or regions "
        "closer than this become one point (the corner of the block or "
        "region given first), and two blocks that overlap in a sliver "
        "thinner than this (twice its area over its perimeter) are taken "
        "as touching: corners computed by trigonometry lie a rounding "
        "error off each other or off the edge they should lie on. A "
        "thicker overlap is an error. 0: exact geometry.");
      prm.declare_entry("Minimum angle",
                        "30",
                        Patterns::Double(10., 33.),
                        "Minimum triangle angle of the Delaunay "
                        "refinement (degrees).");
      prm.enter_subsection("Mesh grading");
      {
        prm.declare_entry(
          "Growth rate",
          "1.3",
          Patterns::Double(1.01, 4.),
          "How fast the mesh coarsens away from a feature given below: the "
          "size bound at distance d from the feature is h + (g - 1) d, so "
          "neighbouring triangles differ in size by about this factor g, up "
          "to the block's own mesh size. Smaller is smoother and costs "
          "more cells.");
        prm.declare_entry(
          "Hole mesh size",
          "0",
          Patterns::Double(0.),
          "Longest triangle edge (m) at the boundary of every hole of every "
          "block and region. 0: no refinement there.");
        prm.declare_entry(
          "Crack tip mesh size",
          "0",
          Patterns::Double(0.),
          "Longest triangle edge (m) at every tip of a pre-existing crack "
          "(and of a dangling joint kept as a crack): an end that lies "
          "inside its block. 0: no refinement there.");
        prm.declare_entry(
          "Notch mesh size",
          "0",
          Patterns::Double(0.),
          "Longest triangle edge (m) at every re-entrant corner of a block "
          "(the material's angle above 190 degrees), where the elastic "
          "stress is singular. 0: no refinement there.");
        prm.declare_entry(
          "Loaded point mesh size",
          "0",
          Patterns::Double(0.),
          "Longest triangle edge (m) at every point where a concentrated "
          "force acts: point loads, the ends of line loads, the points of "
          "boundary conditions and the ends of bolts. 0: no refinement "
          "there.");
        prm.declare_entry(
          "Refinement points",
          "",
          Patterns::Anything(),
          "Further points with their own sizes, 'x, y, size; x, y, size' "
          "(m): the longest triangle edge at the point, growing with the "
          "growth rate away from it (for example where a crack is expected "
          "to start, or where a plate will touch).");
      }
      prm.leave_subsection();
      for (const auto &name : block_names)
        {
          prm.enter_subsection(name);
          prm.declare_entry("Outer boundary",
                            "",
                            Patterns::Anything(),
                            "Polygon 'x, y; x, y; ...' (m), either "
                            "orientation.");
          prm.declare_entry("Holes",
                            "",
                            Patterns::Anything(),
                            "Hole polygons inside the block, separated by "
                            "'|'.");
          prm.declare_entry("Cracks",
                            "",
                            Patterns::Anything(),
                            "Pre-existing crack segments 'x1, y1, x2, y2; "
                            "...' inside the block.");
          declare_mesh_size(prm);
          declare_initial_state(prm);
          prm.leave_subsection();
        }
      for (const auto &name : region_names)
        {
          prm.enter_subsection(name);
          prm.declare_entry("Outer boundary",
                            "",
                            Patterns::Anything(),
                            "Polygon of the rock region 'x, y; ...' (m).");
          prm.declare_entry("Holes",
                            "",
                            Patterns::Anything(),
                            "Hole polygons, separated by '|'.");
          prm.declare_entry("Joints",
                            "",
                            Patterns::Anything(),
                            "Joint segments 'x1, y1, x2, y2; ...' that cut "
                            "the region into blocks.");
          prm.declare_entry("Keep dangling joints as cracks",
                            "true",
                            Patterns::Bool(),
                            "Joint parts that end inside a block become "
                            "cracks of it (true) or are dropped (false).");
          declare_mesh_size(prm);
          declare_initial_state(prm);
          prm.leave_subsection();
        }
      prm.leave_subsection();
    }



    void
    Geometry::parse_parameters(ParameterHandler               &prm,
                               const std::vector<std::string> &block_names,
                               const std::vector<std::string> &region_names,
                               const Materials                &materials,
                               const std::string              &base_directory)
    {
      prm.enter_subsection("Geometry");
      min_angle      = prm.get_double("Minimum angle");
      max_cells      = prm.get_double("Maximum number of cells");
      snap_tolerance = prm.get_double("Snapping tolerance");
      prm.enter_subsection("Mesh grading");
      {
        grading                   = geometry::MeshGrading();
        grading.growth_rate       = prm.get_double("Growth rate");
        grading.hole_size         = prm.get_double("Hole mesh size");
        grading.crack_tip_size    = prm.get_double("Crack tip mesh size");
        grading.notch_size        = prm.get_double("Notch mesh size");
        grading.loaded_point_size = prm.get_double("Loaded point mesh size");
        const std::string entry   = "Geometry/Mesh grading/Refinement points";
        for (const auto &piece : split(prm.get("Refinement points"), ";"))
          {
            const auto numbers = parse_numbers(piece, entry, 3);
            AssertThrow(numbers[2] > 0.,
                        ExcMessage(entry + ": '" + Utilities::trim(piece) +
                                   "' has a size <= 0. Give 'x, y, size' "
                                   "with a size > 0 (m)."));
            grading.refinement_points.emplace_back(Point<2>(numbers[0],
                                                            numbers[1]),
                                                   numbers[2]);
          }
      }
      prm.leave_subsection();
      mesh_file = prm.get("Mesh file");
      if (!mesh_file.empty())
        {
          if (mesh_file.front() != '/')
            mesh_file = base_directory + mesh_file;
          std::ifstream in(mesh_file);
          AssertThrow(in.good(),
                      ExcMessage("Geometry/Mesh file: cannot open '" +
                                 mesh_file +
                                 "'. Check the path; a relative path is "
                                 "taken relative to the .prm file."));
          AssertThrow(!grading.is_active() && grading.loaded_point_size == 0.,
                      ExcMessage("Geometry/Mesh grading: sizes are given "
                                 "together with a Mesh file. Grading applies "
                                 "to Blocks and Regions, which ndda meshes; "
                                 "a mesh file is used as it is. Grade the "
                                 "mesh in gmsh, or set the sizes to 0."));
          AssertThrow(block_names.empty() && region_names.empty(),
                      ExcMessage("Geometry/Mesh file: a mesh file is given "
                                 "together with Blocks or Regions. Use "
                                 "either the mesh file or the polygons."));
          for (const auto &item : split(prm.get("Mesh file materials"), ","))
            {
              const auto pair = Utilities::split_string_list(item, ":");
              AssertThrow(pair.size() == 2,
                          ExcMessage("Geometry/Mesh file materials: '" + item +
                                     "' is not 'tag: material'."));
              const double tag =
                to_double(pair[0], "Geometry/Mesh file materials");
              AssertThrow(tag >= 0 && tag == std::floor(tag),
                          ExcMessage("Geometry/Mesh file materials: '" +
                                     pair[0] + "' is not a physical tag."));
              materials.id(pair[1], "Geometry/Mesh file materials");
              mesh_file_materials.emplace_back(static_cast<unsigned int>(tag),
                                               pair[1]);
            }
        }
      blocks.clear();
      block_states.clear();
      for (const auto &name : block_names)
        {
          const std::string where = "Geometry/" + name;
          prm.enter_subsection(name);
          geometry::BlockDescription block;
          block.name = name;
          block.outer =
            parse_points(prm.get("Outer boundary"), where + "/Outer boundary");
          block.holes  = parse_rings(prm.get("Holes"), where + "/Holes");
          block.cracks = parse_segments(prm.get("Cracks"), where + "/Cracks");
          parse_mesh_size(prm, where, materials, block);
          blocks.push_back(block);
          block_states.push_back(parse_initial_state(prm, where));
          prm.leave_subsection();
        }
      regions.clear();
      region_states.clear();
      for (const auto &name : region_names)
        {
          const std::string where = "Geometry/" + name;
          prm.enter_subsection(name);
          geometry::RegionDescription region;
          region.name = name;
          region.outer =
            parse_points(prm.get("Outer boundary"), where + "/Outer boundary");
          region.holes  = parse_rings(prm.get("Holes"), where + "/Holes");
          region.joints = parse_segments(prm.get("Joints"), where + "/Joints");
          region.keep_dangling_as_cracks =
            prm.get_bool("Keep dangling joints as cracks");
          parse_mesh_size(prm, where, materials, region);
          regions.push_back(region);
          region_states.push_back(parse_initial_state(prm, where));
          prm.leave_subsection();
        }
      prm.leave_subsection();
    }
  } // namespace parameters
} // namespace ndda
