// SPDX-License-Identifier: GPL-3.0-or-later
#include <deal.II/lac/full_matrix.h>

#include <ndda/mesh/state_transfer.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace ndda
{
  namespace state_transfer
  {
    void
    interpolate_moved(
      const dealii::FiniteElement<2>                     &fe,
      const std::vector<dealii::types::global_dof_index> &cell_dofs,
      const std::vector<std::array<unsigned int, 3>>     &triangles,
      const std::vector<unsigned int>                    &moved,
      const std::vector<dealii::Point<2>>                &old_vertices,
      const std::vector<dealii::Point<2>>                &new_vertices,
      const std::vector<dealii::Vector<double> *>        &vectors)
    {
      using dealii::Point;
      if (moved.empty())
        return;
      AssertThrow(fe.has_support_points(),
                  dealii::ExcMessage(
                    "interpolate_moved: the element " + fe.get_name() +
                    " has no support points to carry values to."));
      const unsigned int n           = fe.n_dofs_per_cell();
      const auto        &unit_points = fe.get_unit_support_points();
      std::vector<bool>  is_moved(new_vertices.size(), false);
      for (const unsigned int v : moved)
        is_moved[v] = true;
      // The cells around moved vertices: the only ones whose support points
      // move, and together they cover where the new points fall.
      std::vector<unsigned int> cells;
      for (unsigned int c = 0; c < triangles.size(); ++c)
        if (is_moved[triangles[c][0]] || is_moved[triangles[c][1]] ||
            is_moved[triangles[c][2]])
          cells.push_back(c);

      const auto map = [](const std::vector<Point<2>>       &x,
                          const std::array<unsigned int, 3> &t,
                          const Point<2>                    &xi) {
        return Point<2>(x[t[0]] + xi[0] * (x[t[1]] - x[t[0]]) +
                        xi[1] * (x[t[2]] - x[t[0]]));
      };
      // The old cell that holds p (the largest smallest barycentric
      // coordinate) and p's reference coordinates there.
      const auto locate = [&](const Point<2> &p) {
        double       best = -std::numeric_limits<double>::max();
        unsigned int cell = cells.front();
        Point<2>     xi;
        for (const unsigned int c : cells)
          {
            const auto                &t     = triangles[c];
            const auto                &x     = old_vertices;
            const double               a     = x[t[1]][0] - x[t[0]][0];
            const double               b     = x[t[2]][0] - x[t[0]][0];
            const double               cc    = x[t[1]][1] - x[t[0]][1];
            const double               d     = x[t[2]][1] - x[t[0]][1];
            const double               det   = a * d - b * cc;
            const dealii::Tensor<1, 2> r     = p - x[t[0]];
            const double               s     = (d * r[0] - b * r[1]) / det;
            const double               u     = (a * r[1] - cc * r[0]) / det;
            const double               worst = std::min({s, u, 1. - s - u});
            if (worst > best)
              {
                best = worst;
                cell = c;
                xi   = Point<2>(s, u);
              }
          }
        return std::make_pair(cell, xi);
      };

      // New values, written after all are computed (dofs are shared).
      std::map<dealii::types::global_dof_index, std::vector<double>> values;
      for (const unsigned int c : cells)
        for (unsigned int i = 0; i < n; ++i)
          {
            const auto dof = cell_dofs[std::size_t(c) * n + i];
            if (values.count(dof) != 0)
              continue;
            const Point<2> before =
              map(old_vertices, triangles[c], unit_points[i]);
            const Point<2> after =
              map(new_vertices, triangles[c], unit_points[i]);
            if (before.distance(after) == 0.)
              continue;
            const auto [old_cell, xi] = locate(after);
            const unsigned int component =
              fe.system_to_component_index(i).first;
            std::vector<double> value(vectors.size(), 0.);
            for (unsigned int j = 0; j < n; ++j)
              {
                if (fe.system_to_component_index(j).first != component)
                  continue;
                const double phi = fe.shape_value_component(j, xi, component);
                const auto   source = cell_dofs[std::size_t(old_cell) * n + j];
                for (unsigned int k = 0; k < vectors.size(); ++k)
                  value[k] += phi * (*vectors[k])[source];
              }
            values.emplace(dof, std::move(value));
          }
      for (const auto &[dof, value] : values)
        for (unsigned int k = 0; k < vectors.size(); ++k)
          (*vectors[k])[dof] = value[k];
    }



    namespace
    {
      /** The point of a reference triangle with vertices @p r at @p xi. */
      dealii::Point<2>
      map_reference(const std::array<dealii::Point<2>, 3> &r,
                    const dealii::Point<2>                &xi)
      {
        return dealii::Point<2>(r[0] + xi[0] * (r[1] - r[0]) +
                                xi[1] * (r[2] - r[0]));
      }
    } // namespace



    void
    transfer_refined(
      const dealii::FiniteElement<2>                     &fe,
      const std::vector<dealii::types::global_dof_index> &old_cell_dofs,
      const refinement::RefineResult                     &refined,
      const std::vector<dealii::types::global_dof_index> &new_cell_dofs,
      const std::vector<const dealii::Vector<double> *>  &old_vectors,
      const std::vector<dealii::Vector<double> *>        &new_vectors)
    {
      const std::size_t n = fe.n_dofs_per_cell();
      AssertThrow(old_cell_dofs.size() == refined.n_old_cells * n &&
                    new_cell_dofs.size() == refined.cell_origin.size() * n &&
                    old_vectors.size() == new_vectors.size(),
                  dealii::ExcMessage(
                    "transfer_refined: the cell dofs do not fit the "
                    "refinement, or the vectors do not pair up."));
      AssertThrow(fe.has_support_points(),
                  dealii::ExcMessage("transfer_refined: the element " +
                                     fe.get_name() +
                                     " has no support points."));
      const auto &unit_points = fe.get_unit_support_points();
      for (std::size_t c = 0; c < refined.cell_origin.size(); ++c)
        {
          if (!refined.is_part[c])
            {
              for (std::size_t i = 0; i < n; ++i)
                for (unsigned int k = 0; k < old_vectors.size(); ++k)
                  (*new_vectors[k])[new_cell_dofs[c * n + i]] =
                    (*old_vectors[k])[old_cell_dofs[c * n + i]];
              continue;
            }
          const std::size_t p = refined.cell_origin[c];
          for (unsigned int i = 0; i < n; ++i)
            {
              const dealii::Point<2> xi =
                map_reference(refined.reference_vertices[c], unit_points[i]);
              const unsigned int component =
                fe.system_to_component_index(i).first;
              std::vector<double> value(old_vectors.size(), 0.);
              for (unsigned int j = 0; j < n; ++j)
                {
                  if (fe.system_to_component_index(j).first != component)
                    continue;
                  const double phi = fe.shape_value_component(j, xi, component);
                  for (unsigned int k = 0; k < old_vectors.size(); ++k)
                    value[k] +=
                      phi * (*old_vectors[k])[old_cell_dofs[p * n + j]];
                }
              for (unsigned int k = 0; k < old_vectors.size(); ++k)
                (*new_vectors[k])[new_cell_dofs[c * n + i]] = value[k];
            }
        }
    }



    void
    transfer_refined(
      const dealii::Quadrature<2>                             &quadrature,
      const unsigned int                                       degree,
      const refinement::RefineResult                          &refined,
      std::vector<std::vector<dealii::SymmetricTensor<2, 2>>> &values)
    {
      using Stress           = dealii::SymmetricTensor<2, 2>;
      const unsigned int n_q = quadrature.size();
      const auto        &x_q = quadrature.get_points();
      const auto        &w_q = quadrature.get_weights();
      AssertThrow(values.size() == refined.n_old_cells,
                  dealii::ExcMessage("transfer_refined: one set of values "
                                     "per old cell is needed."));
      // The monomials xi^a eta^b, a + b <= the degree, as many as the
      // points can fix.
      unsigned int fit_degree = degree;
      while ((fit_degree + 1) * (fit_degree + 2) / 2 > n_q)
        --fit_degree;
      const unsigned int n_basis = (fit_degree + 1) * (fit_degree + 2) / 2;
      const auto         basis   = [&](const dealii::Point<2> &x) {
        std::vector<double> phi;
        for (unsigned int total = 0; total <= fit_degree; ++total)
          for (unsigned int b = 0; b <= total; ++b)
            phi.push_back(std::pow(x[0], total - b) * std::pow(x[1], b));
        return phi;
      };
      // The normal equations' matrix is the same for every cell (reference
      // coordinates).
      dealii::FullMatrix<double>       normal(n_basis, n_basis);
      std::vector<std::vector<double>> phi_q;
      for (unsigned int q = 0; q < n_q; ++q)
        {
          phi_q.push_back(basis(x_q[q]));
          for (unsigned int k = 0; k < n_basis; ++k)
            for (unsigned int l = 0; l < n_basis; ++l)
              normal(k, l) += w_q[q] * phi_q[q][k] * phi_q[q][l];
        }
      normal.gauss_jordan();

      // The fit of every old cell that was bisected, before any of its
      // values are overwritten.
      std::map<unsigned int, std::vector<Stress>> fit;
      for (std::size_t c = 0; c < refined.cell_origin.size(); ++c)
        {
          const unsigned int p = refined.cell_origin[c];
          if (!refined.is_part[c] || fit.count(p) != 0)
            continue;
          AssertDimension(values[p].size(), n_q);
          std::vector<Stress> rhs(n_basis), coefficient(n_basis);
          for (unsigned int q = 0; q < n_q; ++q)
            for (unsigned int k = 0; k < n_basis; ++k)
              rhs[k] += w_q[q] * phi_q[q][k] * values[p][q];
          for (unsigned int k = 0; k < n_basis; ++k)
            for (unsigned int l = 0; l < n_basis; ++l)
              coefficient[k] += normal(k, l) * rhs[l];
          fit.emplace(p, std::move(coefficient));
        }
      values.resize(refined.cell_origin.size());
      for (std::size_t c = 0; c < refined.cell_origin.size(); ++c)
        {
          if (!refined.is_part[c])
            continue;
          const auto &coefficient = fit.at(refined.cell_origin[c]);
          values[c].assign(n_q, Stress());
          for (unsigned int q = 0; q < n_q; ++q)
            {
              const auto phi =
                basis(map_reference(refined.reference_vertices[c], x_q[q]));
              for (unsigned int k = 0; k < n_basis; ++k)
                values[c][q] += phi[k] * coefficient[k];
            }
        }
    }
  } // namespace state_transfer
} // namespace ndda
