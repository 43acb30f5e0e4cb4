// SPDX-License-Identifier: GPL-3.0-or-later

#include <ndda/physics/bolts.h>

namespace ndda
{
  void
  BoltSprings::setup(const parameters::Bolts &parameters,
                     const NodeLocator       &nodes)
  {
    bolts.clear();
    for (const auto &b : parameters.bolts)
      {
        const std::string where   = "Bolts/" + b.name + "/End points";
        const Point<2>    ends[2] = {b.first, b.second};
        Spring            bolt;
        for (unsigned int e = 0; e < 2; ++e)
          {
            const auto found = nodes.nodes_at_vertex(ends[e], where);
            AssertThrow(!found.empty(), dealii::ExcInternalError());
            bolt.dofs[2 * e]     = found[0];
            bolt.dofs[2 * e + 1] = nodes.partner[found[0]];
          }
        bolt.first      = b.first;
        bolt.second     = b.second;
        bolt.stiffness  = b.stiffness;
        bolt.pretension = b.pretension;
        bolts.push_back(bolt);
      }
  }



  void
  BoltSprings::add_couplings(dealii::DynamicSparsityPattern &dsp) const
  {
    for (const auto &bolt : bolts)
      for (const auto i : bolt.dofs)
        for (const auto j : bolt.dofs)
          dsp.add(i, j);
  }



  Tensor<1, 2>
  BoltSprings::direction(const Spring &bolt, const Vector<double> &displacement)
  {
    std::array<Point<2>, 2> x = {{bolt.first, bolt.second}};
    for (unsigned int e = 0; e < 2; ++e)
      for (unsigned int d = 0; d < 2; ++d)
        x[e][d] += displacement[bolt.dofs[2 * e + d]];
    return (x[0] - x[1]) / x[0].distance(x[1]);
  }



  void
  BoltSprings::add_stiffness(const Vector<double>         &displacement,
                             dealii::SparseMatrix<double> &matrix) const
  {
    // Thesis 3.6: k_b L L^T with L the unit vector between the anchors on
    // the current geometry.
    for (const auto &bolt : bolts)
      {
        const Tensor<1, 2> l = direction(bolt, displacement);
        for (unsigned int a = 0; a < 2; ++a)
          for (unsigned int b = 0; b < 2; ++b)
            for (unsigned int i = 0; i < 2; ++i)
              for (unsigned int j = 0; j < 2; ++j)
                matrix.add(bolt.dofs[2 * a + i],
                           bolt.dofs[2 * b + j],
                           (a == b ? 1. : -1.) * bolt.stiffness * l[i] * l[j]);
      }
  }



  void
  BoltSprings::add_internal_force(const Vector<double> &displacement,
                                  Vector<double>       &force) const
  {
    for (const auto &bolt : bolts)
      {
        const Tensor<1, 2> l = direction(bolt, displacement);
        for (unsigned int d = 0; d < 2; ++d)
          {
            force[bolt.dofs[d]] += bolt.axial_force * l[d];
            force[bolt.dofs[2 + d]] -= bolt.axial_force * l[d];
          }
      }
  }



  void
  BoltSprings::add_pretension(const Vector<double> &displacement,
                              Vector<double>       &force) const
  {
    for (const auto &bolt : bolts)
      if (bolt.pretension != 0.)
        {
          const Tensor<1, 2> l = direction(bolt, displacement);
          for (unsigned int d = 0; d < 2; ++d)
            {
              force[bolt.dofs[d]] -= bolt.pretension * l[d];
              force[bolt.dofs[2 + d]] += bolt.pretension * l[d];
            }
        }
  }



  void
  BoltSprings::update(const Vector<double> &displacement,
                      const Vector<double> &d)
  {
    for (auto &bolt : bolts)
      {
        const Tensor<1, 2> l          = direction(bolt, displacement);
        double             elongation = 0;
        for (unsigned int c = 0; c < 2; ++c)
          elongation += l[c] * (d[bolt.dofs[c]] - d[bolt.dofs[2 + c]]);
        bolt.axial_force += bolt.stiffness * elongation;
      }
  }



  std::vector<double>
  BoltSprings::axial_forces() const
  {
    std::vector<double> forces;
    for (const auto &bolt : bolts)
      forces.push_back(bolt.axial_force);
    return forces;
  }



  void
  BoltSprings::set_axial_forces(const std::vector<double> &forces)
  {
    AssertDimension(forces.size(), bolts.size());
    for (unsigned int b = 0; b < bolts.size(); ++b)
      bolts[b].axial_force = forces[b];
  }
} // namespace ndda
