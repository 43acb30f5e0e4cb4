// SPDX-License-Identifier: GPL-3.0-or-later
//
// The built-in VTU fields. Their names are part of ndda's interface
// (README, DESIGN.md): displacement, velocity, stress_xx, stress_yy,
// stress_xy, principal_stress_1, principal_stress_2, nodal_stress_xx,
// nodal_stress_yy, nodal_stress_xy, nodal_principal_stress_1,
// nodal_principal_stress_2, block_id, material_id, crack_faces.

#include <deal.II/numerics/data_out.h>

#include <ndda/base/atomic_file.h>
#include <ndda/postprocess/postprocessor.h>
#include <ndda/postprocess/stress_recovery.h>
#include <ndda/simulator.h>

#include <fstream>
#include <iomanip>
#include <map>

namespace ndda
{
  namespace postprocess
  {
    using namespace dealii;

    namespace
    {
      /** Add the dof vector @p v as the vector field @p name. */
      void
      add_vector_field(Frame                &frame,
                       const Vector<double> &v,
                       const std::string    &name)
      {
        const std::vector<
          DataComponentInterpretation::DataComponentInterpretation>
          kind(2, DataComponentInterpretation::component_is_part_of_vector);
        frame.data_out.add_data_vector(v,
                                       std::vector<std::string>(2, name),
                                       DataOut<2>::type_dof_data,
                                       kind);
      }

      /** A cell field of the frame, from one value per active cell. */
      template <typename ValueOfCell>
      void
      add_cell_field(const Simulator<2> &simulator,
                     Frame              &frame,
                     const std::string  &name,
                     const ValueOfCell  &value_of_cell)
      {
        const unsigned int n_cells =
          simulator.get_mesh().get_triangulation().n_active_cells();
        Vector<double> &values = frame.new_cell_vector(n_cells);
        for (unsigned int c = 0; c < n_cells; ++c)
          values[c] = value_of_cell(c);
        frame.data_out.add_data_vector(values,
                                       name,
                                       DataOut<2>::type_cell_data);
      }

      /** The larger (@p sign 1) or smaller (-1) principal stress of @p s. */
      double
      principal_stress(const SymmetricTensor<2, 2> &s, const double sign)
      {
        const double mean = 0.5 * (s[0][0] + s[1][1]);
        return mean + sign * std::hypot(0.5 * (s[0][0] - s[1][1]), s[0][1]);
      }
    } // namespace



    /** Total displacement since the start (m). */
    class DisplacementField : public Postprocessor
    {
    public:
      void
      add_fields(const Simulator<2> &simulator, Frame &frame) const override
      {
        add_vector_field(frame, simulator.get_displacement(), "displacement");
      }
    };



    /** Velocity (m/s). */
    class VelocityField : public Postprocessor
    {
    public:
      void
      add_fields(const Simulator<2> &simulator, Frame &frame) const override
      {
        add_vector_field(frame, simulator.get_velocity(), "velocity");
      }
    };



    /** The cell's mean stress and its principal stresses (Pa). */
    class StressFields : public Postprocessor
    {
    public:
      void
      add_fields(const Simulator<2> &simulator, Frame &frame) const override
      {
        const auto principal = [&](const unsigned int c, const double sign) {
          return principal_stress(simulator.mean_cell_stress(c), sign);
        };
        const auto component = [&](const unsigned int i, const unsigned int j) {
          return [&simulator, i, j](const unsigned int c) {
            return simulator.mean_cell_stress(c)[i][j];
          };
        };
        add_cell_field(simulator, frame, "stress_xx", component(0, 0));
        add_cell_field(simulator, frame, "stress_yy", component(1, 1));
        add_cell_field(simulator, frame, "stress_xy", component(0, 1));
        add_cell_field(simulator,
                       frame,
                       "principal_stress_1",
                       [&](const unsigned int c) { return principal(c, 1.); });
        add_cell_field(simulator,
                       frame,
                       "principal_stress_2",
                       [&](const unsigned int c) { return principal(c, -1.); });
      }
    };



    /**
     * The stresses recovered at the nodes (StressRecovery: the L2
     * projection onto the element's own space, or for a linear element
     * the patch recovery, piece by piece) and their
     * principal stresses, as point fields (Pa).
     */
    class NodalStressFields : public Postprocessor
    {
    public:
      void
      add_fields(const Simulator<2> &simulator, Frame &frame) const override
      {
        auto &recovery = frame.keep(std::make_unique<StressRecovery>());
        recovery.recover(simulator);
        const auto &dofs       = recovery.get_dof_handler();
        const auto &components = recovery.get_components();
        const char *names[]    = {"nodal_stress_xx",
                                  "nodal_stress_yy",
                                  "nodal_stress_xy"};
        for (unsigned int k = 0; k < 3; ++k)
          frame.data_out.add_data_vector(dofs, components[k], names[k]);
        for (const double sign : {1., -1.})
          {
            Vector<double> &values = frame.new_cell_vector(dofs.n_dofs());
            for (unsigned int i = 0; i < values.size(); ++i)
              values[i] = principal_stress(recovery.at_dof(i), sign);
            frame.data_out.add_data_vector(dofs,
                                           values,
                                           sign > 0 ?
                                             "nodal_principal_stress_1" :
                                             "nodal_principal_stress_2");
          }
      }
    };



    /** The block and the material of every cell. */
    class BlockAndMaterial : public Postprocessor
    {
    public:
      void
      add_fields(const Simulator<2> &simulator, Frame &frame) const override
      {
        const auto &mesh = simulator.get_mesh();
        add_cell_field(simulator, frame, "block_id", [&](const unsigned int c) {
          return mesh.block_of_cell(c);
        });
        std::vector<unsigned int> material;
        for (const auto &cell :
             mesh.get_triangulation().active_cell_iterators())
          material.push_back(cell->material_id());
        add_cell_field(simulator,
                       frame,
                       "material_id",
                       [&](const unsigned int c) { return material[c]; });
      }
    };



    /**
     * The number of each cell's sides that are crack faces (pre-existing
     * or new), and with VTU output a file cracks-NNNNN.txt of every crack
     * face as a segment on the present geometry. The faces of a fresh
     * crack touch, so without these a picture cannot tell them from an
     * unbroken edge.
     */
    class CrackFaces : public Postprocessor
    {
    public:
      void
      add_fields(const Simulator<2> &simulator, Frame &frame) const override
      {
        const auto        &block_mesh = simulator.get_mesh().get_block_mesh();
        const unsigned int n_cells =
          simulator.get_mesh().get_triangulation().n_active_cells();
        Vector<double> &crack_faces = frame.new_cell_vector(n_cells);
        // A crack face is a side of its cell with the same vertex order.
        // The index is built only when the scene has crack faces.
        if (!block_mesh.crack_edges.empty())
          {
            std::map<std::pair<unsigned int, unsigned int>, unsigned int>
              side_of;
            for (unsigned int c = 0; c < block_mesh.triangles.size(); ++c)
              for (unsigned int j = 0; j < 3; ++j)
                side_of[{block_mesh.triangles[c][j],
                         block_mesh.triangles[c][(j + 1) % 3]}] = c;
            for (const auto &e : block_mesh.crack_edges)
              {
                const auto side = side_of.find({e[0], e[1]});
                if (side != side_of.end() && side->second < n_cells)
                  crack_faces[side->second] += 1.;
              }
          }
        frame.data_out.add_data_vector(crack_faces,
                                       "crack_faces",
                                       DataOut<2>::type_cell_data);
        if (!frame.write_vtu || block_mesh.crack_edges.empty() ||
            !simulator.writes_files())
          return;
        AtomicFile file(frame.directory + "cracks-" +
                        Utilities::int_to_string(frame.number, 5) + ".txt");
        auto      &cracks = file.stream();
        cracks << "# crack faces at t = " << simulator.get_time()
               << " s: x1 y1 x2 y2 (m), one face per line\n"
               << std::setprecision(10);
        for (const auto &e : block_mesh.crack_edges)
          cracks << block_mesh.vertices[e[0]] << ' '
                 << block_mesh.vertices[e[1]] << '\n';
        file.commit();
      }
    };



    NDDA_REGISTER_PLUGIN(Postprocessor,
                         DisplacementField,
                         "displacement",
                         "VTU field 'displacement': the total displacement "
                         "since the start (m, vector).")
    NDDA_REGISTER_PLUGIN(Postprocessor,
                         VelocityField,
                         "velocity",
                         "VTU field 'velocity' (m/s, vector).")
    NDDA_REGISTER_PLUGIN(
      Postprocessor,
      StressFields,
      "stress",
      "VTU cell fields 'stress_xx', 'stress_yy', 'stress_xy', "
      "'principal_stress_1' and 'principal_stress_2': the area-weighted "
      "mean stress of each cell (Pa, tension positive).")
    NDDA_REGISTER_PLUGIN(
      Postprocessor,
      NodalStressFields,
      "nodal stress",
      "VTU point fields 'nodal_stress_xx', 'nodal_stress_yy', "
      "'nodal_stress_xy', 'nodal_principal_stress_1' and "
      "'nodal_principal_stress_2': the stresses at the quadrature points "
      "projected (L2) onto the element's own continuous space, for linear "
      "elements recovered by Zienkiewicz-Zhu patches instead, within each "
      "piece of the mesh, never across a crack or between blocks (Pa, "
      "tension positive). Right at peaks on boundaries where the cell "
      "means lie a third of a cell inside; drawn with the element's "
      "subdivisions (P2: quadratic).")
    NDDA_REGISTER_PLUGIN(Postprocessor,
                         BlockAndMaterial,
                         "block and material",
                         "VTU cell fields 'block_id' and 'material_id'.")
    NDDA_REGISTER_PLUGIN(
      Postprocessor,
      CrackFaces,
      "crack faces",
      "VTU cell field 'crack_faces' (how many of the cell's sides are crack "
      "faces) and, with VTU output and once the scene has crack faces, "
      "cracks-NNNNN.txt beside each frame: every crack face as 'x1 y1 x2 "
      "y2' on the present geometry.")
  } // namespace postprocess
} // namespace ndda
