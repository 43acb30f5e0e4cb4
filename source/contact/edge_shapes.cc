// SPDX-License-Identifier: GPL-3.0-or-later
//
// The shape functions along a triangle's edges, sampled for the options of
// the contacts (doc/contact.md, "Kernels").

#include <deal.II/base/point.h>

#include <ndda/contact/edge_shapes.h>

#include <algorithm>
#include <cmath>

namespace ndda
{
  namespace contact
  {
    namespace
    {
      using dealii::Point;

      /** Vertices of the reference triangle (deal.II's numbering). */
      const Point<2> unit_vertex[3] = {Point<2>(0, 0),
                                       Point<2>(1, 0),
                                       Point<2>(0, 1)};
    } // namespace



    void
    EdgeShapes::initialize(const dealii::FiniteElement<2> &fe_in)
    {
      fe               = &fe_in;
      n_points         = fe->degree + 1;
      sampled          = fe->degree >= 1 && n_points <= max_points;
      const auto point = [](const unsigned int k, const double c) {
        return Point<2>(unit_vertex[k] +
                        c * (unit_vertex[(k + 1) % 3] - unit_vertex[k]));
      };
      for (unsigned int k = 0; k < 3 && sampled; ++k)
        {
          edge_dofs[k].clear();
          samples[k].clear();
          for (unsigned int i = 0; i < fe->n_dofs_per_cell(); ++i)
            {
              std::vector<double> v(n_points);
              double              largest = 0;
              for (unsigned int j = 0; j < n_points; ++j)
                {
                  v[j] = fe->shape_value(i, point(k, double(j) / fe->degree));
                  largest = std::max(largest, std::abs(v[j]));
                }
              if (largest <= 1e-13)
                continue; // vanishes on the edge (checked below)
              edge_dofs[k].push_back(i);
              samples[k].insert(samples[k].end(), v.begin(), v.end());
            }
        }
      // The interpolation must reproduce every function at points between
      // the samples, the vanishing ones included; else evaluate directly.
      std::vector<double> value(fe->n_dofs_per_cell());
      for (unsigned int k = 0; k < 3 && sampled; ++k)
        for (const double c : {0.2718281828, 0.6180339887})
          {
            std::fill(value.begin(), value.end(), 0.);
            values(k, c, value.data());
            std::vector<double> on_edge(fe->n_dofs_per_cell(), 0.);
            for (unsigned int q = 0; q < edge_dofs[k].size(); ++q)
              on_edge[edge_dofs[k][q]] = value[q];
            for (unsigned int i = 0; i < fe->n_dofs_per_cell(); ++i)
              if (std::abs(on_edge[i] - fe->shape_value(i, point(k, c))) >
                  1e-12)
                sampled = false;
          }
      if (!sampled)
        for (unsigned int k = 0; k < 3; ++k)
          {
            edge_dofs[k].resize(fe->n_dofs_per_cell());
            for (unsigned int i = 0; i < fe->n_dofs_per_cell(); ++i)
              edge_dofs[k][i] = i;
          }
    }



    void
    EdgeShapes::values(const unsigned int k,
                       const double       c,
                       double            *values) const
    {
      const unsigned int n = edge_dofs[k].size();
      if (!sampled)
        {
          const Point<2> xi =
            unit_vertex[k] + c * (unit_vertex[(k + 1) % 3] - unit_vertex[k]);
          for (unsigned int q = 0; q < n; ++q)
            values[q] = fe->shape_value(edge_dofs[k][q], xi);
          return;
        }
      // Lagrange basis on the points j / p.
      const unsigned int p = n_points - 1;
      double             basis[max_points];
      for (unsigned int j = 0; j <= p; ++j)
        {
          basis[j] = 1;
          for (unsigned int m = 0; m <= p; ++m)
            if (m != j)
              basis[j] *= (c * p - m) / (double(j) - m);
        }
      const double *sample = samples[k].data();
      for (unsigned int q = 0; q < n; ++q, sample += n_points)
        {
          double v = 0;
          for (unsigned int j = 0; j <= p; ++j)
            v += sample[j] * basis[j];
          values[q] = v;
        }
    }
  } // namespace contact
} // namespace ndda
