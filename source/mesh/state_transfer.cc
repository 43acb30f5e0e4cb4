// SPDX-License-Identifier: GPL-3.0-or-later
#include <ndda/mesh/state_transfer.h>

#include <algorithm>
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
  } // namespace state_transfer
} // namespace ndda
