// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_contact_contact_law_h
#define ndda_contact_contact_law_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <ndda/base/plugin_registry.h>
#include <ndda/contact/contact_parameters.h>

#include <boost/container/small_vector.hpp>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace ndda
{
  namespace contact
  {
    using dealii::ParameterHandler;
    using dealii::Tensor;
    using dealii::types::global_dof_index;

    /**
     * State of one contact in the open-close iteration (thesis 2.3.13,
     * 3.10).
     */
    enum class State : unsigned char
    {
      /// No spring.
      open,
      /// Normal spring and shear spring: the vertex sticks to its anchor
      /// point on the edge.
      locked,
      /// Normal spring and Coulomb friction along the edge.
      sliding,
      /// A vertex-vertex pair whose reference edge is not chosen yet, held
      /// by a temporary spring between the two vertices (thesis 6.2). Not
      /// a state of a contact law: the handler's vertex-vertex resolution
      /// owns it.
      vertex_spring
    };

    class ContactLaw;

    /**
     * Material data and stiffnesses the contacts of a scene need: the
     * ContactHandler's settings, which it hands to the contact law with
     * every call.
     */
    struct ContactSettings
    {
      /// Normal spring stiffness (N/m).
      double normal_stiffness = 0;
      /// Shear spring stiffness over normal spring stiffness.
      double shear_ratio = 0.4;
      /// Vertex-vertex resolution.
      parameters::VertexVertexMethod vertex_vertex_method =
        parameters::VertexVertexMethod::revised;
      /// Hysteresis of the open-close criteria (m): a closed contact opens
      /// when its gap exceeds this, an open one closes when it penetrates
      /// deeper than this, and a sliding one locks when it moves back by
      /// more than this.
      double state_tolerance = 0;
      /// A vertex-edge candidate that starts deeper than this inside the
      /// other body, with no contact remembered from the last step, is not
      /// a contact (the far face of a block thinner than the detection
      /// distance, m).
      double ignore_depth = 0;
      /// The weight of the contact forces at the step's start in the
      /// integrator's step (TimeIntegrator::contact_start_weight(): 0 for
      /// Shi's scheme, 1/2 for Newmark, alpha_f for generalized-α); the
      /// end forces have 1 minus it.
      double start_weight = 0;
      /// Joint strength per metre of contact length (N/m): tensile
      /// strength and cohesion of the joint material times the thickness.
      /// Contacts that touch at the start of the run are bonded with it
      /// until they break (see doc/contact.md, "Bonded joints"), if the
      /// contact law bonds joints.
      double bond_tension  = 0;
      double bond_cohesion = 0;
      /// The contact law. Empty: ContactHandler::initialize() sets the
      /// default law, "penalty Coulomb" with its default parameters.
      std::shared_ptr<const ContactLaw> law;
    };

    /**
     * One option of a contact: a vertex against the line of one boundary
     * edge, with its linearised gap operators, on the geometry of the
     * step's start. A vertex-edge contact has one option; a vertex-vertex
     * pair has one per potential reference edge (thesis chapter 6).
     *
     * The normal gap is linearised in the step's increment d as
     * g(d) = gap + e_n . d and the tangential motion as e_t . d; the
     * entries of e_n and e_t on the option's dofs are @p wn and @p wt
     * (doc/contact.md, "Kernels").
     */
    struct Option
    {
      /// The vertex (index into the mesh's vertices).
      unsigned int vertex;
      /// The edge (index into the boundary edges).
      unsigned int edge;
      /// Outward unit normal and unit tangent (v0 -> v1) of the edge.
      Tensor<1, 2> normal, tangent;
      /// Length of the edge (m).
      double length;
      /// Projection ratio of the vertex on the edge, not clamped.
      double ratio;
      /// Signed distance of the vertex to the edge's line (positive
      /// outside), less the contact's offset once a contact has chosen
      /// this option.
      double gap;
      /// Dofs of the vertex, then of the nodes of the edge's cell whose
      /// shape functions do not vanish on the edge (its two vertices with
      /// P1, and its midpoint with P2): on the others e_n and e_t are 0.
      /// Kept in place up to P2 (no allocation per option).
      boost::container::small_vector<global_dof_index, 8> dofs;
      /// Gap operators e_n and e_t on those dofs.
      boost::container::small_vector<double, 8> wn, wt;

      /** The normal gap g(d) = gap + e_n . d after the increment @p d. */
      double
      normal_gap(const dealii::Vector<double> &d) const;

      /** The tangential motion e_t . d of the vertex along the edge. */
      double
      tangential_increment(const dealii::Vector<double> &d) const;

      /**
       * The shear displacement (m) of the vertex from the anchor point at
       * ratio @p anchor along the edge's line, after the tangential
       * motion @p increment: s = (ratio - anchor) length + increment.
       */
      double
      shear_displacement(const double anchor, const double increment) const
      {
        return (ratio - anchor) * length + increment;
      }
    };

    /**
     * What a contact law knows of a contact besides its option: the state
     * of the open-close iteration and the data of the springs.
     */
    struct ContactState
    {
      /// open, locked or sliding for a law (vertex_spring only for the
      /// handler's unresolved vertex-vertex pairs, which no law sees).
      State state = State::open;
      /// Anchor of the shear spring, as a ratio along the option's edge
      /// line (outside [0, 1] for a vertex beyond the edge's end).
      double anchor = 0;
      /// Sliding direction along the edge's tangent (+1, -1; 0 without
      /// friction or when not sliding).
      int sign = 0;
      /// Friction coefficient mu of the contact (tan of the smaller joint
      /// friction angle of the two sides).
      double friction = 0;
      /// Length of joint a bonded contact stands for (m), see
      /// doc/contact.md, "Bonded joints"; 0 for a contact without bond.
      double bond_length = 0;
      /// The normal gap (m) of the contact on its chosen option in the
      /// last solve of this step's open-close iteration in which it was
      /// closed; NaN before such a solve, and after one in which it was
      /// open or that gave it another option. A law whose forces lag one solve
      /// behind (force_lags()) takes them from it; no stiffness may depend on
      /// it.
      double solved_gap = std::numeric_limits<double>::quiet_NaN();
    };

    /**
     * The motion of a contact in a trial solution d of the open-close
     * iteration, on the option it is classified on.
     */
    struct Trial
    {
      /** The trial of option @p o under the increment @p d. */
      Trial(const Option &o, const dealii::Vector<double> &d);

      /** A trial given by its two numbers. */
      Trial(const double gap, const double increment);

      /// Normal gap g(d) at the end of the step (m, negative: penetration).
      double gap;
      /// Tangential motion e_t . d of the vertex along the edge in the step
      /// (m).
      double increment;
    };

    inline double
    Option::normal_gap(const dealii::Vector<double> &d) const
    {
      double g = gap;
      for (unsigned int k = 0; k < dofs.size(); ++k)
        g += wn[k] * d[dofs[k]];
      return g;
    }



    inline double
    Option::tangential_increment(const dealii::Vector<double> &d) const
    {
      double s = 0;
      for (unsigned int k = 0; k < dofs.size(); ++k)
        s += wt[k] * d[dofs[k]];
      return s;
    }



    inline Trial::Trial(const Option &o, const dealii::Vector<double> &d)
      : gap(o.normal_gap(d))
      , increment(o.tangential_increment(d))
    {}



    inline Trial::Trial(const double gap, const double increment)
      : gap(gap)
      , increment(increment)
    {}



    /**
     * Interface of a contact law: what happens in a contact between a
     * vertex and an edge once the handler has found it and chosen the edge
     * (the narrow phase and the vertex-vertex resolution of thesis chapter
     * 6 are geometry and stay in ContactHandler). A law decides
     *
     * - the springs of a contact in a given state: their stiffness and
     *   their forces at d = 0 (add_springs());
     * - the state of a contact after a trial solution of the open-close
     *   iteration: open, locked or sliding with a direction (classify()),
     *   and where a contact that locks anchors its shear spring
     *   (anchor_on_locking());
     * - whether contacts that touch when the run starts are bonded, and
     *   whether a bond holds under a trial solution
     *   (bonds_initial_contacts(), bond_holds(); the default is a law
     *   without bonds);
     * - the energy stored in a contact's springs (energy()).
     *
     * All functions are const: a law holds its parameters only, and one
     * object may serve every contact of a scene. The scene-wide data (the
     * penalty stiffness, which the automatic penalty changes during a run;
     * the shear stiffness ratio; the state tolerance; the joint strength)
     * come with every call in the ContactSettings. The handler calls
     * classify(), bond_holds() and anchor_on_locking() for different
     * contacts on several threads at once: they must not change anything
     * but what they return (no caches, no counters).
     *
     * A law is a plugin in the style of ASPECT: a class derived from this
     * one, with a static `declare_parameters(ParameterHandler &)` that
     * declares its entries (the caller has entered the law's own
     * subsection, named after the law, inside `subsection Contact`), an
     * override of parse_parameters() that reads them, and one line
     * NDDA_REGISTER_CONTACT_LAW(Class, "name", "description") at the end of
     * its `.cc` file. `set Contact law = name` in `subsection Contact`
     * selects the law of a scene (ContactSettings::law).
     *
     * @ingroup contact
     */
    class ContactLaw
    {
    public:
      virtual ~ContactLaw() = default;

      /**
       * Read the law's parameters. The caller has entered the law's
       * subsection. The default reads nothing.
       */
      virtual void
      parse_parameters(ParameterHandler &prm);

      /**
       * Add the springs of a contact in state @p contact.state (locked or
       * sliding) on option @p o, all stiffnesses times @p scale: their
       * forces at d = 0 to @p force and, unless @p stiffness is null, their
       * stiffness to @p stiffness. The stiffness must be a function of
       * @p o, @p contact, @p scale and @p settings alone: within a step the
       * handler asks for it once per contact and state, and later
       * open-close solves in the same state reuse it (asking for the
       * forces only).
       *
       * @param o The option the contact acts on.
       * @param contact Its state, anchor, sliding direction and friction.
       * @param scale Factor on all stiffnesses (the fraction of a step's
       *   force the Newmark integrator uses, 1 otherwise).
       * @param settings The scene's contact settings.
       * @param stiffness Null, or a square matrix of the size of o.dofs,
       *   indexed like o.dofs, to which the stiffness is added (it may be
       *   non-symmetric).
       * @param force A vector indexed by global dof (the entries of
       *   o.dofs) to which the forces at d = 0 are added.
       */
      virtual void
      add_springs(const Option               &o,
                  const ContactState         &contact,
                  const double                scale,
                  const ContactSettings      &settings,
                  dealii::FullMatrix<double> *stiffness,
                  dealii::Vector<double>     &force) const = 0;

      /**
       * The state of a contact, resolved on option @p o and in state
       * @p contact.state (open, locked or sliding), after the trial
       * solution @p trial: the open-close criteria and the friction limit.
       *
       * @param sign Set to the sliding direction of the new state (+1 or
       *   -1 if it is sliding with friction, 0 otherwise).
       * @return open, locked or sliding.
       */
      virtual State
      classify(const Option          &o,
               const ContactState    &contact,
               const Trial           &trial,
               const ContactSettings &settings,
               int                   &sign) const = 0;

      /**
       * The anchor (a ratio along the edge's line) of the shear spring of
       * a contact that locks after the trial solution @p trial, having been
       * in state @p contact.state. The default anchors it at the vertex's
       * projection at the step's start, o.ratio.
       */
      virtual double
      anchor_on_locking(const Option          &o,
                        const ContactState    &contact,
                        const Trial           &trial,
                        const ContactSettings &settings) const;

      /**
       * Whether contacts that touch when the run starts are bonded with
       * the joint strength of @p settings. The default: never.
       */
      virtual bool
      bonds_initial_contacts(const ContactSettings &settings) const;

      /**
       * Whether the bond of a bonded, locked contact holds under the trial
       * solution @p trial. A bond that does not hold is broken for good;
       * the contact is then classified by classify(). The default: it
       * does not hold (a law that bonds must override this).
       */
      virtual bool
      bond_holds(const Option          &o,
                 const ContactState    &contact,
                 const Trial           &trial,
                 const ContactSettings &settings) const;

      /**
       * The energy (J) stored in the springs of a contact in state
       * @p contact.state (locked or sliding) on option @p o at the end of
       * the step with the solution @p trial.
       */
      virtual double
      energy(const Option          &o,
             const ContactState    &contact,
             const Trial           &trial,
             const ContactSettings &settings) const = 0;

      /**
       * The energy (J) that friction dissipated in a contact that ends the
       * step sliding (state @p contact.state) on option @p o with the
       * solution @p trial: the friction force the integrator applied over
       * the step times the slip, for the statistics' energy balance
       * ('Friction dissipation (J)'). The default: none (a law without
       * friction).
       */
      virtual double
      friction_dissipation(const Option          &o,
                           const ContactState    &contact,
                           const Trial           &trial,
                           const ContactSettings &settings) const;

      /**
       * Whether a force that add_springs() gave a contact for the solve
       * that produced @p trial (in state @p contact.state, from
       * @p contact.solved_gap, the gap of the solve before) lagged behind
       * that solve by more than the law accepts. If so for any contact,
       * the open-close iteration solves again in the same states
       * (OpenCloseSolver; such solves do not count towards its limit on
       * state changes). Called before the contact is classified. The
       * default: no force of the law lags (false).
       */
      virtual bool
      force_lags(const Option          &o,
                 const ContactState    &contact,
                 const Trial           &trial,
                 const ContactSettings &settings) const;

      /**
       * Whether force_lags() can be true for any contact with the law's
       * parameters: false lets the open-close iteration skip asking each
       * contact after every solve. The default: true, so that a law that
       * overrides force_lags() need not override this too.
       */
      virtual bool
      forces_may_lag() const;

      /** For messages (PluginRegistry). */
      static const char *
      plugin_kind()
      {
        return "contact law";
      }

      static const char *
      plugin_kinds()
      {
        return "contact laws";
      }

      static const char *
      selection_entry()
      {
        return "Contact/Contact law";
      }

      /** Keep the built-in laws in every program. */
      static void
      link_builtin_plugins();
    };

    /** The registry of contact laws. */
    using ContactLawRegistry = PluginRegistry<ContactLaw>;

    /**
     * Register a contact law under @p name. Called by
     * NDDA_REGISTER_CONTACT_LAW before main() runs; throws if the name is
     * taken.
     *
     * @param name Name of the law and of its own subsection.
     * @param description What the law does; it documents the law's
     *   selection and its parameters.
     * @param declare_parameters Declares the law's entries.
     * @param create Creates a law with default parameters.
     */
    void
    register_contact_law(const std::string &name,
                         const std::string &description,
                         void (*declare_parameters)(ParameterHandler &),
                         std::unique_ptr<ContactLaw> (*create)());

    /** The names of all registered laws, sorted. */
    std::vector<std::string>
    contact_law_names();

    /** The description a law was registered with. */
    std::string
    contact_law_description(const std::string &name);

    /**
     * Declare, in the subsection the caller has entered (`Contact`), one
     * subsection per registered law with that law's entries.
     */
    void
    declare_contact_law_parameters(ParameterHandler &prm);

    /**
     * Create the law called @p name with its default parameters. Throws
     * dealii::ExcMessage naming the name received and the known names if
     * @p name is not registered.
     */
    std::unique_ptr<ContactLaw>
    create_contact_law(const std::string &name);

    /**
     * Create the law called @p name and read its parameters from its
     * subsection of the subsection the caller has entered (`Contact`), as
     * declared by declare_contact_law_parameters().
     */
    std::unique_ptr<ContactLaw>
    create_contact_law(const std::string &name, ParameterHandler &prm);

    /** Name of the law ContactHandler uses when ContactSettings has none. */
    inline const std::string default_contact_law = "penalty Coulomb";

  } // namespace contact
} // namespace ndda

/**
 * Register the contact law @p classname (derived from
 * ndda::contact::ContactLaw, default constructible, with a static
 * declare_parameters(ParameterHandler &)) under @p name with
 * @p description: NDDA_REGISTER_PLUGIN for this interface. Put it at the
 * end of the law's `.cc` file, inside the namespace of @p classname.
 */
#define NDDA_REGISTER_CONTACT_LAW(classname, name, description) \
  NDDA_REGISTER_PLUGIN(ndda::contact::ContactLaw, classname, name, description)

#endif
