// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_scene_scene_parameters_h
#define ndda_scene_scene_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <ndda/geometry/block_mesh.h>
#include <ndda/physics/physics_parameters.h>

#include <array>
#include <string>
#include <utility>
#include <vector>

namespace ndda
{
  /**
   * The parameters that scene/ reads: subsection Geometry (blocks,
   * regions or a mesh file, and the initial state of each block).
   *
   * @ingroup parameters
   */
  namespace parameters
  {
    /** Per-block initial state, given beside the block's geometry. */
    struct InitialState
    {
      /// sigma_xx, sigma_yy, sigma_xy (Pa, tension positive).
      std::array<double, 3> stress = {{0., 0., 0.}};
      /// Velocity components as functions of x, y (muparser).
      std::string velocity = "0; 0";
      /// The subsection it was read from (e.g. "Geometry/disc"), for
      /// messages.
      std::string where = "Geometry";
      /// The block kinematics model the block starts with (a name of
      /// kinematics::BlockKinematicsRegistry); empty: Control/Kinematics.
      std::string kinematics;
    };

    /** subsection Geometry */
    struct Geometry
    {
      std::vector<geometry::BlockDescription>  blocks;
      std::vector<geometry::RegionDescription> regions;
      /// Initial state, one per block, then one per region.
      std::vector<InitialState> block_states;
      std::vector<InitialState> region_states;
      std::string               mesh_file;
      /// For a mesh file: the material name of each physical surface tag
      /// ("tag: material, ..."), empty means material id = tag.
      std::vector<std::pair<unsigned int, std::string>> mesh_file_materials;
      double                                            min_angle;
      /// Geometry/Maximum number of cells.
      double max_cells;
      /// Snapping tolerance, relative to the scene's size.
      double snap_tolerance;
      /// Geometry/Mesh grading (its loaded points are filled in by the
      /// scene, from the loads and boundary conditions).
      geometry::MeshGrading grading;

      static void
      declare_parameters(ParameterHandler               &prm,
                         const std::vector<std::string> &block_names,
                         const std::vector<std::string> &region_names);
      void
      parse_parameters(ParameterHandler               &prm,
                       const std::vector<std::string> &block_names,
                       const std::vector<std::string> &region_names,
                       const Materials                &materials,
                       const std::string              &base_directory);
    };

  } // namespace parameters
} // namespace ndda

#endif
