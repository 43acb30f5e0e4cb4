// SPDX-License-Identifier: GPL-3.0-or-later

#include <deal.II/base/exceptions.h>

#include <deal.II/fe/fe_values.h>

#include <ndda/base/utilities.h>
#include <ndda/physics/loads.h>

namespace ndda
{
  using namespace dealii;

  Tensor<1, 2>
  PointEvaluator::value(const Vector<double> &v) const
  {
    Tensor<1, 2> result;
    for (unsigned int i = 0; i < dofs.size(); ++i)
      result[component[i]] += shape_values[i] * v[dofs[i]];
    return result;
  }



  PointEvaluator
  make_point_evaluator(const CrackableMesh    &mesh,
                       const FiniteElement<2> &fe,
                       const DofMap           &dof_map,
                       const Point<2>         &p,
                       const std::string      &entry)
  {
    // deal.II 9.4's find_active_cell_around_point() can return a cell of
    // another block on meshes of disconnected blocks; locate by
    // barycentric coordinates instead.
    const auto [cell_index, unit_point] = mesh.locate(p);
    AssertThrow(cell_index != numbers::invalid_unsigned_int,
                ExcMessage(entry + ": the point " + to_string(p) +
                           " lies outside every block. Move it into or onto "
                           "a block."));
    PointEvaluator evaluator;
    evaluator.cell = cell_index;
    evaluator.dofs.assign(dof_map.dofs_of_cell(cell_index),
                          dof_map.dofs_of_cell(cell_index) +
                            dof_map.dofs_per_cell);
    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
      {
        evaluator.shape_values.push_back(fe.shape_value(i, unit_point));
        evaluator.component.push_back(fe.system_to_component_index(i).first);
      }
    return evaluator;
  }



  void
  ExternalLoads::setup(const parameters::Loads &loads_in,
                       const CrackableMesh     &mesh,
                       const DoFHandler<2>     &dof_handler,
                       const DofMap            &dof_map)
  {
    loads = loads_in;
    gravity =
      std::make_unique<Expression>(loads.gravity, 2, true, "Loads/Gravity");
    point_functions.clear();
    point_evaluators.clear();
    for (const auto &load : loads.point_loads)
      {
        point_functions.push_back(std::make_unique<Expression>(
          load.force, 2, true, "Loads/" + load.name + "/Force"));
        point_evaluators.push_back(
          make_point_evaluator(mesh,
                               dof_handler.get_fe(),
                               dof_map,
                               load.point,
                               "Loads/" + load.name + "/Point"));
      }

    line_functions.clear();
    loaded_faces.clear();
    const auto   box       = mesh.bounding_box();
    const double tolerance = point_tolerance(box.first, box.second);
    for (unsigned int l = 0; l < loads.line_loads.size(); ++l)
      {
        const auto &load = loads.line_loads[l];
        line_functions.push_back(
          std::make_unique<Expression>(load.value,
                                       load.is_pressure ? 1 : 2,
                                       true,
                                       "Loads/" + load.name + "/Value"));
        unsigned int n_faces = 0;
        for (const auto &cell : dof_handler.active_cell_iterators())
          for (unsigned int f = 0; f < cell->n_faces(); ++f)
            if (cell->at_boundary(f) &&
                distance_to_segment(cell->face(f)->vertex(0), load.segment) <=
                  tolerance &&
                distance_to_segment(cell->face(f)->vertex(1), load.segment) <=
                  tolerance)
              {
                LoadedFace face;
                face.line_load = l;
                face.cell      = cell->active_cell_index();
                face.face      = f;
                loaded_faces.push_back(face);
                ++n_faces;
              }
        AssertThrow(n_faces > 0,
                    ExcMessage("Loads/" + load.name +
                               "/Segment: no boundary edge lies on the "
                               "segment " +
                               to_string(load.segment.a) + " - " +
                               to_string(load.segment.b) +
                               ". Give a segment along a block's boundary."));
      }
    for (auto &g : gravity_load)
      g.reinit(dof_map.n_dofs);
  }



  void
  ExternalLoads::update_faces(const DoFHandler<2> &dof_handler,
                              const Mapping<2>    &mapping,
                              const Quadrature<1> &face_quadrature,
                              const double         thickness)
  {
    const auto     &fe = dof_handler.get_fe();
    FEFaceValues<2> fe_face_values(mapping,
                                   fe,
                                   face_quadrature,
                                   update_values | update_JxW_values |
                                     update_normal_vectors |
                                     update_quadrature_points);
    std::vector<typename DoFHandler<2>::active_cell_iterator> cells;
    for (const auto &cell : dof_handler.active_cell_iterators())
      cells.push_back(cell);
    for (auto &face : loaded_faces)
      {
        const auto &cell = cells[face.cell];
        fe_face_values.reinit(cell, face.face);
        face.dofs.resize(fe.n_dofs_per_cell());
        cell->get_dof_indices(face.dofs);
        face.component.clear();
        face.weighted_shape.clear();
        face.points.clear();
        face.normals.clear();
        for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
          face.component.push_back(fe.system_to_component_index(i).first);
        for (unsigned int q = 0; q < face_quadrature.size(); ++q)
          {
            std::vector<double> w(fe.n_dofs_per_cell());
            for (unsigned int i = 0; i < w.size(); ++i)
              w[i] =
                fe_face_values.shape_value_component(i, q, face.component[i]) *
                fe_face_values.JxW(q) * thickness;
            face.weighted_shape.push_back(w);
            face.points.push_back(fe_face_values.quadrature_point(q));
            face.normals.push_back(fe_face_values.normal_vector(q));
          }
      }
  }



  void
  ExternalLoads::update_gravity(const SparseMatrix<double> &mass,
                                const DofMap               &dof_map)
  {
    // M times a unit acceleration in each direction.
    for (unsigned int d = 0; d < 2; ++d)
      {
        Vector<double> unit(dof_map.n_dofs);
        for (const auto &dofs : dof_map.node_dofs)
          unit[dofs[d]] = 1.;
        gravity_load[d].reinit(dof_map.n_dofs);
        mass.vmult(gravity_load[d], unit);
      }
  }



  void
  ExternalLoads::check_expressions(const std::vector<double> &times)
  {
    gravity->check({Point<2>()}, times);
    for (unsigned int l = 0; l < point_functions.size(); ++l)
      point_functions[l]->check({loads.point_loads[l].point}, times);
    std::vector<std::vector<Point<2>>> points(line_functions.size());
    for (const auto &face : loaded_faces)
      points[face.line_load].insert(points[face.line_load].end(),
                                    face.points.begin(),
                                    face.points.end());
    for (unsigned int l = 0; l < line_functions.size(); ++l)
      line_functions[l]->check(points[l], times);
  }



  void
  ExternalLoads::add(const double t, Vector<double> &force) const
  {
    // Gravity, thesis 3.5.3 with consistent loads: f = M g.
    const Point<2> origin;
    for (unsigned int d = 0; d < 2; ++d)
      {
        gravity->set_time(t);
        const double g = gravity->value(origin, d);
        if (g != 0.)
          force.add(g, gravity_load[d]);
      }
    // Point loads, thesis 3.5.1: f = N^T p at the material point.
    for (unsigned int l = 0; l < point_evaluators.size(); ++l)
      {
        const auto &evaluator = point_evaluators[l];
        point_functions[l]->set_time(t);
        const auto &p = loads.point_loads[l].point;
        for (unsigned int i = 0; i < evaluator.dofs.size(); ++i)
          force[evaluator.dofs[i]] +=
            evaluator.shape_values[i] *
            point_functions[l]->value(p, evaluator.component[i]);
      }
    // Line loads, thesis 3.5.2, integrated with the element's own shape
    // functions on the face.
    for (const auto &face : loaded_faces)
      {
        auto &function = *line_functions[face.line_load];
        function.set_time(t);
        const bool pressure = loads.line_loads[face.line_load].is_pressure;
        for (unsigned int q = 0; q < face.points.size(); ++q)
          {
            Tensor<1, 2> traction;
            if (pressure)
              traction = -function.value(face.points[q], 0) * face.normals[q];
            else
              for (unsigned int d = 0; d < 2; ++d)
                traction[d] = function.value(face.points[q], d);
            for (unsigned int i = 0; i < face.dofs.size(); ++i)
              force[face.dofs[i]] +=
                face.weighted_shape[q][i] * traction[face.component[i]];
          }
      }
  }
} // namespace ndda
