// SPDX-License-Identifier: GPL-3.0-or-later
//
// Helpers of the tests of scenes whose blocks are loaded through plates
// (the Brazilian discs): the plate force from the plate's contacts, the
// kinetic energy of some blocks, blocks by name.
#ifndef ndda_tests_plates_h
#define ndda_tests_plates_h

#include <ndda/fracture/fracture_criterion.h>
#include <ndda/postprocess/block_forces.h>
#include <ndda/simulator.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "tests.h"

namespace ndda_tests
{
  /**
   * The load P on plate @p block: the vertical component of the contact
   * forces on its nodes at the end of the last step (compression
   * positive; postprocess::contact_force_on_block(), the 'block forces'
   * statistics columns). The plates are rigid blocks: they have no stress
   * to read the load from.
   */
  inline double
  plate_force(const ndda::Simulator<2> &simulator, const unsigned int block)
  {
    return std::abs(
      ndda::postprocess::contact_force_on_block(simulator, block)[1]);
  }

  /** Kinetic energy of the blocks whose name starts with @p prefix. */
  inline double
  kinetic_energy_of(const ndda::Simulator<2> &simulator,
                    const std::string        &prefix)
  {
    const auto            &mesh  = simulator.get_mesh();
    const auto            &names = mesh.get_block_names();
    const auto            &v     = simulator.get_velocity();
    dealii::Vector<double> mv(v.size());
    simulator.get_mass_matrix().vmult(mv, v);
    std::vector<bool>                            in(v.size(), false);
    std::vector<dealii::types::global_dof_index> dofs;
    for (const auto &cell : simulator.get_dof_handler().active_cell_iterators())
      if (names[mesh.block_of_cell(cell->active_cell_index())].rfind(prefix,
                                                                     0) == 0)
        {
          dofs.resize(cell->get_fe().n_dofs_per_cell());
          cell->get_dof_indices(dofs);
          for (const auto i : dofs)
            in[i] = true;
        }
    double energy = 0;
    for (unsigned int i = 0; i < v.size(); ++i)
      if (in[i])
        energy += 0.5 * v[i] * mv[i];
    return energy;
  }

  inline unsigned int
  block_index(const ndda::Simulator<2> &simulator, const std::string &name)
  {
    const auto &names = simulator.get_mesh().get_block_names();
    const auto  i     = std::find(names.begin(), names.end(), name);
    check(i != names.end(), "block " + name + " exists");
    return i - names.begin();
  }

  inline std::string
  mode_name(const ndda::fracture::FailureMode mode)
  {
    return mode == ndda::fracture::FailureMode::tension ? "tension" :
           mode == ndda::fracture::FailureMode::shear   ? "shear" :
                                                          "none";
  }

  /** Crack faces near the loaded (vertical) diameter and elsewhere. */
  struct DiameterCracks
  {
    unsigned int n_near = 0, n_far = 0; // faces within / beyond the band
    double       y_low = 0, y_high = 0; // extent of those within it
  };

  /**
   * The crack faces whose midpoints lie within @p half_width of the line
   * x = 0, their lowest and highest midpoint (0 if none), and the number
   * of the others.
   */
  inline DiameterCracks
  diameter_cracks(const ndda::Simulator<2> &simulator, const double half_width)
  {
    const auto    &mesh = simulator.get_mesh().get_block_mesh();
    DiameterCracks result;
    for (const auto &e : mesh.crack_edges)
      {
        const dealii::Point<2> m =
          0.5 * (mesh.vertices[e[0]] + mesh.vertices[e[1]]);
        if (std::abs(m[0]) < half_width)
          {
            ++result.n_near;
            result.y_low  = std::min(result.y_low, m[1]);
            result.y_high = std::max(result.y_high, m[1]);
          }
        else
          ++result.n_far;
      }
    return result;
  }
} // namespace ndda_tests

#endif
