// SPDX-License-Identifier: GPL-3.0-or-later
//
// Extending ndda without touching it: a program that links the library and
// brings its own
//
//  1. contact law: "slip weakening", Coulomb friction whose coefficient
//     drops to a fraction of the static one once a contact slides (a
//     joint's residual friction);
//  2. time integrator: "backward Euler", v1 = d / dt (first order,
//     dissipative);
//  3. constitutive law: "damaged elasticity", linear elasticity with the
//     stiffness reduced by a damage variable D, C = (1 - D) C0;
//  4. postprocessor: "block displacement", the mean displacement of every
//     block as statistics columns;
//  5. element: "FE_RockP", a finite element class registered with deal.II
//     under a name of its own, selected by `set Finite element`.
//
// Each plugin is one class and one registration line, NDDA_REGISTER_PLUGIN,
// as the built-in ones are (include/ndda/base/plugin_registry.h); the
// scene selects them by name in its .prm text, which also holds their
// parameters. ndda's --print-parameters of this program would list them.
//
// The program runs two scenes and checks what they must show:
//
//  a. A block launched down a 30 degree incline at 1 m/s; static friction
//     angle 35 degrees (tan = 0.700 > tan 30 = 0.577: with plain Coulomb
//     friction it would brake and stop), residual friction half of it once
//     sliding: it accelerates at a = g (sin 30 - 0.35 cos 30) = 1.93 m/s^2.
//     Its displacement along the slope after 0.5 s must be v0 t + a t^2 / 2
//     within 2 %, read from the user's postprocessor's column of the
//     statistics file.
//  b. A block standing on fixed ground under gravity, quasi-static: the
//     stresses are those of equilibrium whatever the stiffness, so with
//     D = 0.5 the strain energy must be twice that of linear elasticity.

#include <deal.II/base/mpi.h>

#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_tools.h>
// Debian's libdeal.ii 9.4.1 exports no FETools::add_fe_name<2, 2>: this
// program instantiates it.
#include <deal.II/fe/fe_tools.templates.h>

#include <ndda/contact/penalty_coulomb.h>
#include <ndda/parameters/parameters.h>
#include <ndda/physics/constitutive_law.h>
#include <ndda/postprocess/postprocessor.h>
#include <ndda/simulator.h>
#include <ndda/time/time_integrator.h>

#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>

namespace user
{
  using namespace dealii;
  using namespace ndda;

  /**
   * 1. A contact law: Coulomb friction that weakens while a contact
   * slides. The built-in penalty Coulomb law does everything else; only
   * the friction coefficient of a sliding contact changes.
   */
  class SlipWeakening : public contact::PenaltyCoulomb
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("Residual friction ratio",
                        "0.5",
                        Patterns::Double(0., 1.),
                        "Friction coefficient of a sliding contact over "
                        "that of a locked one.");
    }

    void
    parse_parameters(ParameterHandler &prm) override
    {
      ratio = prm.get_double("Residual friction ratio");
    }

    void
    add_springs(const contact::Option          &o,
                const contact::ContactState    &c,
                const double                    scale,
                const contact::ContactSettings &settings,
                FullMatrix<double>             *stiffness,
                Vector<double>                 &force) const override
    {
      PenaltyCoulomb::add_springs(
        o, weakened(c), scale, settings, stiffness, force);
    }

    contact::State
    classify(const contact::Option          &o,
             const contact::ContactState    &c,
             const contact::Trial           &trial,
             const contact::ContactSettings &settings,
             int                            &sign) const override
    {
      return PenaltyCoulomb::classify(o, weakened(c), trial, settings, sign);
    }

    double
    anchor_on_locking(const contact::Option          &o,
                      const contact::ContactState    &c,
                      const contact::Trial           &trial,
                      const contact::ContactSettings &settings) const override
    {
      return PenaltyCoulomb::anchor_on_locking(o, weakened(c), trial, settings);
    }

  private:
    /** The contact as the law sees it: residual friction while sliding. */
    contact::ContactState
    weakened(const contact::ContactState &c) const
    {
      contact::ContactState w = c;
      if (c.state == contact::State::sliding)
        w.friction *= ratio;
      return w;
    }

    double ratio = 0.5;
  };

  NDDA_REGISTER_PLUGIN(contact::ContactLaw,
                       SlipWeakening,
                       "slip weakening",
                       "Coulomb friction whose coefficient drops to "
                       "'Residual friction ratio' times the static one "
                       "while a contact slides (example program).")



  /**
   * 2. A time integrator: backward Euler. The step's increment is
   * d = v1 dt with v1 = v0 + a1 dt, so M a1 = M (d - v0 dt) / dt^2: the
   * step matrix has c_M = 1 / dt^2 and the right-hand side M v0 / dt.
   */
  class BackwardEuler : public time::TimeIntegrator
  {
  public:
    double
    mass_coefficient(const double dt) const override
    {
      return 1. / (dt * dt);
    }

    void
    add_inertia_terms(const SparseMatrix<double> &mass,
                      const time::KinematicState &start,
                      const double                dt,
                      Vector<double>             &rhs) const override
    {
      Vector<double> mv(start.velocity);
      mv /= dt;
      mass.vmult_add(rhs, mv);
    }

    void
    update(const Vector<double> &d,
           const double          dt,
           const SparseMatrix<double> &,
           const Vector<double> &,
           time::KinematicState &state) const override
    {
      state.velocity = d;
      state.velocity /= dt;
    }
  };

  NDDA_REGISTER_PLUGIN(time::TimeIntegrator,
                       BackwardEuler,
                       "backward Euler",
                       "v1 = d / dt, a1 = (v1 - v0) / dt: first order, "
                       "unconditionally stable, dissipative (example "
                       "program).")



  /**
   * 3. A constitutive law: isotropic linear elasticity whose stiffness a
   * damage variable D reduces, C = (1 - D) C0. The interface's defaults
   * give the linear stress update and the elastic energy.
   */
  class DamagedElasticity : public ConstitutiveLaw
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("Damage",
                        "0",
                        Patterns::Double(0., 0.99),
                        "The damage variable D in [0, 0.99].");
    }

    void
    parse_parameters(ParameterHandler &prm) override
    {
      damage = prm.get_double("Damage");
    }

    SymmetricTensor<4, 2>
    tangent(const parameters::Material &m,
            const bool                  plane_strain) const override
    {
      return (1. - damage) * isotropic_elasticity_tensor(m.youngs_modulus,
                                                         m.poissons_ratio,
                                                         plane_strain);
    }

  private:
    double damage = 0;
  };

  NDDA_REGISTER_PLUGIN(ConstitutiveLaw,
                       DamagedElasticity,
                       "damaged elasticity",
                       "Linear elasticity with the stiffness times (1 - "
                       "Damage) (example program).")



  /**
   * 4. A postprocessor: the mean displacement of the vertices of every
   * block, two statistics columns per block.
   */
  class BlockDisplacement : public postprocess::Postprocessor
  {
  public:
    void
    add_statistics(const Simulator<2>           &simulator,
                   postprocess::StatisticsTable &statistics) const override
    {
      const auto         &mesh = simulator.get_mesh();
      const auto         &u    = simulator.get_displacement();
      std::vector<double> sum_x(mesh.n_blocks()), sum_y(mesh.n_blocks()),
        count(mesh.n_blocks());
      for (const auto &cell :
           simulator.get_dof_handler().active_cell_iterators())
        {
          const unsigned int b = mesh.block_of_cell(cell->active_cell_index());
          for (unsigned int v = 0; v < cell->n_vertices(); ++v)
            {
              sum_x[b] += u[cell->vertex_dof_index(v, 0)];
              sum_y[b] += u[cell->vertex_dof_index(v, 1)];
              count[b] += 1;
            }
        }
      for (unsigned int b = 0; b < mesh.n_blocks(); ++b)
        {
          const std::string name = mesh.get_block_names()[b];
          postprocess::add_scientific(statistics,
                                      name + " u_x (m)",
                                      sum_x[b] / count[b]);
          postprocess::add_scientific(statistics,
                                      name + " u_y (m)",
                                      sum_y[b] / count[b]);
        }
    }
  };

  NDDA_REGISTER_PLUGIN(postprocess::Postprocessor,
                       BlockDisplacement,
                       "block displacement",
                       "Mean displacement of the vertices of every block "
                       "(statistics; example program).")



  /** The last value of column @p column of a statistics file. */
  double
  last_value(const std::string &file, const std::string &column)
  {
    std::ifstream in(file);
    std::string   line;
    unsigned int  index = 0, n_columns = 0;
    bool          found = false;
    double        value = std::nan("");
    while (std::getline(in, line))
      if (line.rfind("# ", 0) == 0)
        {
          ++n_columns;
          if (line.find(column) != std::string::npos)
            {
              index = n_columns - 1;
              found = true;
            }
        }
      else if (found && !line.empty())
        {
          std::istringstream row(line);
          std::string        entry;
          for (unsigned int i = 0; i <= index; ++i)
            row >> entry;
          value = std::stod(entry);
        }
    return value;
  }
} // namespace user



namespace
{
  /** The materials, shared by both scenes, with @p law_lines and
   * Young's modulus @p modulus. */
  std::string
  materials(const std::string &law_lines, const std::string &modulus = "10e9")
  {
    return R"(
      subsection Materials
        set Names = rock
)" + law_lines +
           R"(
        subsection rock
          set Density         = 2600
          set Young's modulus = )" +
           modulus + R"(
          set Poisson's ratio = 0.25
          set Joint friction angle = 35
        end
      end
    )";
  }

  /** a. The block launched down the incline. */
  bool
  check_slide()
  {
    const double                 g = 9.81, v0 = 1., t = 0.5;
    const double                 sin30 = 0.5, cos30 = std::sqrt(3.) / 2.;
    const std::string            scene = R"(
      set Scene name = user_plugins_slide
      subsection Control
        set Time integrator = backward Euler
        set Finite element  = FE_RockP(1)
        set Time step       = 1e-3
        set End time        = 0.5
        set Maximum displacement ratio = 0.01
      end
      subsection Contact
        set Contact law = slip weakening
        subsection slip weakening
          set Residual friction ratio = 0.5
        end
      end
      subsection Geometry
        set Blocks = incline, block
        subsection incline
          set Outer boundary = 0, 0; 4.3301270189221936, 0; 4.3301270189221936, 2.4999999999999996
          set Material  = rock
          set Mesh size = 1
        end
        subsection block
          set Outer boundary = 3.0310889132455356, 1.7499999999999998; 3.897114317029974, 2.2499999999999996; 3.647114317029974, 2.6830127018922187; 2.7810889132455356, 2.1830127018922192
          set Material  = rock
          set Mesh size = 0.5
          set Initial velocity = -0.8660254037844386; -0.5
        end
      end
      subsection Loads
        set Gravity = 0; -9.81
      end
      subsection Boundary conditions
        set Names = ground
        subsection ground
          set Type     = fixed
          set Segments = 0, 0, 4.3301270189221936, 0; 4.3301270189221936, 0, 4.3301270189221936, 2.4999999999999996
        end
      end
      subsection Postprocess
        set List of postprocessors = time step, block displacement
      end
      subsection Output
        set Interval  = 0.5
        set Write vtu = false
      end
    )" + materials("");
    ndda::parameters::Parameters parameters;
    dealii::ParameterHandler     prm;
    parameters.read(scene, "user_plugins_slide.prm", prm);
    ndda::Simulator<2> simulator(parameters);
    simulator.run();

    // Down the slope is (-cos 30, -sin 30).
    const std::string file = parameters.output.directory + "statistics";
    const double      ux   = user::last_value(file, "block u_x (m)");
    const double      uy   = user::last_value(file, "block u_y (m)");
    const double      s    = -(ux * cos30 + uy * sin30);
    const double a = g * (sin30 - 0.5 * std::tan(35. * M_PI / 180.) * cos30);
    const double expected = v0 * t + 0.5 * a * t * t;
    const double error    = std::abs(s - expected) / expected;
    std::cout << "a. slide down the incline in " << t << " s: " << s
              << " m, expected " << expected << " m (a = " << a
              << " m/s^2), error " << 100 * error << " %" << std::endl;
    return std::isfinite(s) && error < 0.02;
  }

  /** b. The strain energy of a block under its weight, for a law and
   * Young's modulus @p modulus. */
  double
  strain_energy(const std::string &law_lines,
                const std::string &modulus = "10e9")
  {
    const std::string            scene = R"(
      set Scene name = user_plugins_column
      subsection Control
        set Analysis type = quasi-static
        set Time step     = 1
        set End time      = 1
      end
      subsection Contact
        set Enable = false
      end
      subsection Geometry
        set Blocks = column
        subsection column
          set Outer boundary = 0, 0; 1, 0; 1, 2; 0, 2
          set Material  = rock
          set Mesh size = 0.25
        end
      end
      subsection Loads
        set Gravity = 0; -9.81
      end
      subsection Boundary conditions
        set Names = ground
        subsection ground
          set Type     = fixed
          set Segments = 0, 0, 1, 0
        end
      end
      subsection Output
        set Write vtu = false
      end
    )" + materials(law_lines, modulus);
    ndda::parameters::Parameters parameters;
    dealii::ParameterHandler     prm;
    parameters.read(scene, "user_plugins_column.prm", prm);
    ndda::Simulator<2> simulator(parameters);
    simulator.do_time_step();
    return simulator.strain_energy();
  }

  bool
  check_damage()
  {
    const double linear  = strain_energy("");
    const double damaged = strain_energy(R"(
        set Constitutive law = damaged elasticity
        subsection damaged elasticity
          set Damage = 0.5
        end
)");
    // Damage 0.5 is linear elasticity at half the modulus: the same run
    // to round-off. (The ratio to the undamaged energy is 2 only to the
    // order of the strain: ndda's strain is the stretch of the polar
    // decomposition, not the linear strain; doc/theory.md.)
    const double half = strain_energy("", "5e9");
    std::cout << "b. strain energy of the column: " << linear
              << " J (linear elasticity), " << damaged << " J (damage 0.5), "
              << half << " J (linear elasticity, half the modulus), ratio "
              << damaged / linear << std::endl;
    return linear > 0 && std::abs(damaged / half - 1.) < 1e-9;
  }
} // namespace



int
main(int argc, char **argv)
{
  using namespace dealii;
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  try
    {
      // 5. An element under a name of its own: any FiniteElement class
      // with a factory; here deal.II's P_k triangle as "FE_RockP".
      FETools::add_fe_name<2, 2>("FE_RockP",
                                 new FETools::FEFactory<FE_SimplexP<2>>());

      const bool slide  = check_slide();
      const bool damage = check_damage();
      if (!slide || !damage)
        {
          std::cout << "FAILED:" << (slide ? "" : " slide")
                    << (damage ? "" : " damage") << std::endl;
          return 1;
        }
      return 0;
    }
  catch (const std::exception &exc)
    {
      std::cerr << "ndda: error: " << exc.what() << std::endl;
      return 1;
    }
}
