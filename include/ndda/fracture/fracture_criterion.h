// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_fracture_fracture_criterion_h
#define ndda_fracture_fracture_criterion_h

#include <deal.II/base/parameter_handler.h>

#include <ndda/base/plugin_registry.h>
#include <ndda/fracture/edge_stress.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace ndda
{
  namespace fracture
  {
    using dealii::ParameterHandler;

    /**
     * Strength of the intact material of a block, in the units ndda uses
     * everywhere (Pa, radians).
     */
    struct Strength
    {
      /// Cohesion c (Pa).
      double cohesion = 0.;
      /// Internal friction angle phi (radians, in [0, pi/2)). The `.prm`
      /// file gives it in degrees (Materials/<name>/Friction angle).
      double friction_angle = 0.;
      /// Tensile strength T (Pa, positive).
      double tensile_strength = 0.;
    };

    /** How an edge fails. */
    enum class FailureMode
    {
      none,
      tension,
      shear
    };

    /**
     * Whether and when in a step an edge fails.
     */
    struct EdgeFailure
    {
      /// FailureMode::none if the edge does not fail within the step.
      FailureMode mode = FailureMode::none;
      /// Failure time as a fraction of the step, in [0, 1]: 0 is the start
      /// of the step (the edge was beyond its strength already), 1 its end.
      /// Meaningless if mode is none.
      double time = 1.;

      /** Whether the edge fails within the step. */
      bool
      fails() const
      {
        return mode != FailureMode::none;
      }
    };

    /**
     * First time in [0, 1] at which a quantity that varies linearly from
     * @p excess_start at the start of the step to @p excess_end at its end
     * becomes positive (thesis 5.27 and 5.33, with the corrections of
     * doc/fracture.md): 0 if @p excess_start > 0 (already beyond the
     * limit), excess_start / (excess_start - excess_end) if
     * excess_start <= 0 < excess_end, and no value otherwise (a state that
     * only touches the limit, or leaves it, does not fail).
     */
    std::optional<double>
    limit_crossing_time(const double excess_start, const double excess_end);

    /**
     * The earlier of a tensile and a shear failure time (thesis 5.34), each
     * empty if that mode does not fail within the step; tension on a tie.
     */
    EdgeFailure
    earlier_failure(const std::optional<double> &tension_time,
                    const std::optional<double> &shear_time);

    /**
     * Interface of a fracture criterion: given the state of an edge at the
     * start and at the end of a step and the strength of its material, does
     * the edge fail within the step, when and how? Inside the step the
     * stresses are taken to vary linearly in time (thesis 5.24, 5.25).
     *
     * A criterion is a plugin in the style of ASPECT: a class derived from
     * this one, with a static `declare_parameters(ParameterHandler &)` that
     * declares its entries (the caller has entered the criterion's own
     * subsection, named after the criterion, inside `subsection Fracture`),
     * an override of parse_parameters() that reads them, and one line
     * NDDA_REGISTER_FRACTURE_CRITERION(Class, "name", "description") at the
     * end of its `.cc` file. `set Criterion = name` in `subsection Fracture`
     * selects it.
     *
     * @ingroup fracture
     */
    class FractureCriterion
    {
    public:
      virtual ~FractureCriterion() = default;

      /**
       * Read the criterion's parameters. The caller has entered the
       * criterion's subsection. The default reads nothing.
       */
      virtual void
      parse_parameters(ParameterHandler &prm);

      /**
       * Whether, when and how the edge fails within the step.
       *
       * @param start The edge's state at the start of the step.
       * @param end The edge's state at the end of the step, computed with
       *   the same edge orientation.
       * @param strength Strength of the edge's material.
       * @return The failure; if two modes fail within the step, the earlier
       *   one (thesis 5.34), tension on a tie.
       */
      virtual EdgeFailure
      failure_in_step(const EdgeState &start,
                      const EdgeState &end,
                      const Strength  &strength) const = 0;

      /**
       * Why a material of @p strength would fail under (almost) any load
       * from its first instant, or an empty string if it would not. A
       * criterion whose limit is zero at zero stress (no cohesion, no
       * tensile strength) makes the failure time of every loaded edge 0
       * (limit_crossing_time() of an excess that starts at 0), so the
       * first crack event splits all of them at once and the block falls
       * apart into its cells in step 1; the parameters refuse such a
       * material before the run. The default finds nothing.
       */
      virtual std::string
      fails_under_any_load(const Strength &strength) const;

      /** For messages (PluginRegistry). */
      static const char *
      plugin_kind()
      {
        return "fracture criterion";
      }

      static const char *
      plugin_kinds()
      {
        return "fracture criteria";
      }

      static const char *
      selection_entry()
      {
        return "Fracture/Criterion";
      }

      /** Keep the built-in criteria in every program. */
      static void
      link_builtin_plugins();
    };

    /** The registry of fracture criteria. */
    using FractureCriterionRegistry = PluginRegistry<FractureCriterion>;

    /**
     * Register a fracture criterion under @p name
     * (FractureCriterionRegistry::add()). Called by
     * NDDA_REGISTER_FRACTURE_CRITERION before main() runs; throws if the
     * name is taken.
     *
     * @param name Name for `set Criterion = ...` and of the criterion's own
     *   subsection.
     * @param description What the criterion does; it becomes part of the
     *   documentation of the Criterion entry.
     * @param declare_parameters Declares the criterion's entries.
     * @param create Creates a criterion with default parameters.
     */
    void
    register_fracture_criterion(const std::string &name,
                                const std::string &description,
                                void (*declare_parameters)(ParameterHandler &),
                                std::unique_ptr<FractureCriterion> (*create)());

    /** The names of all registered criteria, sorted. */
    std::vector<std::string>
    fracture_criterion_names();

    /**
     * The names of all registered criteria joined by '|', for a
     * dealii::Patterns::Selection.
     */
    std::string
    fracture_criterion_selection();

    /**
     * Create the criterion called @p name with its default parameters.
     * Throws dealii::ExcMessage naming the entry Fracture/Criterion, the
     * name received and the known names if @p name is not registered.
     */
    std::unique_ptr<FractureCriterion>
    create_fracture_criterion(const std::string &name);

  } // namespace fracture

  namespace parameters
  {
    using dealii::ParameterHandler;

    /**
     * The parameters of `subsection Fracture` that fracture itself reads:
     * which criterion (and the criterion's own parameters) and how edge
     * stresses are formed.
     */
    struct Fracture
    {
      /// `set Edge stress = cell average | nodal average | nonlocal
      /// average`.
      fracture::EdgeStressMethod edge_stress_method =
        fracture::EdgeStressMethod::cell_average;
      /// `set Nonlocal radius`: the radius R (m) of the nonlocal average;
      /// positive exactly when the edge stress is the nonlocal average.
      double nonlocal_radius = 0;
      /// Name of the selected criterion, `set Criterion = ...`.
      std::string criterion_name;
      /// Split failing edges (else only count them).
      bool split_edges = true;
      /// Fraction of the step after the earliest failure within which
      /// failing edges crack in the same event.
      double crack_window = 0;
      /// Crack events per step at most.
      unsigned int max_crack_events = 50;
      /// `set Crack path`: true for `maximum tangential stress` (a failure
      /// near a crack tip advances the tip in the direction of the maximum
      /// tangential stress, the mesh aligned to it: fracture/crack_tips.h),
      /// false for `mesh edges` (the failing edge cracks, thesis 5.3).
      bool align_crack_paths = false;
      /// `set Tip mesh size`: the longest edge (m) the mesh is refined to
      /// around every crack tip after each crack event (longest-edge
      /// bisection, CrackableMesh::refine()); 0: no refinement.
      double tip_mesh_size = 0;
      /// The selected criterion with its parameters read; stateless, so it
      /// may be shared.
      std::shared_ptr<const fracture::FractureCriterion> criterion;

      /**
       * Declare, in `subsection Fracture` (entered and left here), the
       * entries Criterion and Edge stress and one subsection per registered
       * criterion with that criterion's entries.
       */
      static void
      declare_parameters(ParameterHandler &prm);

      /** Read what declare_parameters() declared; create the criterion. */
      void
      parse_parameters(ParameterHandler &prm);
    };

  } // namespace parameters
} // namespace ndda

/**
 * Register the fracture criterion @p classname (derived from
 * ndda::fracture::FractureCriterion, default constructible, with a static
 * declare_parameters(ParameterHandler &)) under @p name with
 * @p description: NDDA_REGISTER_PLUGIN for this interface. Put it at the
 * end of the criterion's `.cc` file, inside the namespace of @p classname.
 */
#define NDDA_REGISTER_FRACTURE_CRITERION(classname, name, description) \
  NDDA_REGISTER_PLUGIN(ndda::fracture::FractureCriterion,              \
                       classname,                                      \
                       name,                                           \
                       description)

#endif
