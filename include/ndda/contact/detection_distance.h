// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_contact_detection_distance_h
#define ndda_contact_detection_distance_h

namespace ndda
{
  namespace contact
  {
    /**
     * How far from an edge a vertex is a candidate contact of a step
     * (doc/contact.md, "Detection").
     *
     * A contact can close within a step only if its gap at the step's
     * start is at most the relative displacement of its two sides, at most
     * twice the step's largest displacement increment. Shi's DDA detects
     * within twice the largest increment the step control allows,
     * 2 x `Control/Maximum displacement ratio` x half the scene's height:
     * a distance that grows with the scene, not with the motion. In a tall
     * wall that settles by micrometres a step it reaches bricks two courses
     * away, and every candidate is a coupling in the system matrix.
     *
     * The rule `motion` detects within four times the last accepted step's
     * largest increment (twice for the two sides, twice for a step whose
     * motion grows), scaled by the square of the step size's growth, and
     * at least a floor of 1 % of Shi's distance; it follows a growing
     * motion at once and a slowing one by at most 10 % a step. To this it
     * adds twice the deepest a vertex lay behind its contact's edge at the
     * last step's end: detection measures the distance from an edge on
     * either side, and a contact that penetrates deeper than the distance
     * would not be found (a soft penalty lets a landing block sink by
     * more than its step's motion). Shi's distance is the most. An attempt
     * whose largest increment is more than half the distance it was
     * detected with may have missed a contact: covers() says so, and the
     * step is detected again with widen()'s distance and solved again at
     * the same size (not a cut). At Shi's distance covers() is always
     * true: the step control's own limit on the increment then holds. The
     * rule `scene` is Shi's distance in every step.
     */
    class DetectionDistance
    {
    public:
      enum class Rule
      {
        /// Shi's distance in every step (the default).
        scene,
        /// Follows the motion of the last step.
        motion
      };

      /** The fraction of Shi's distance that the rule `motion` keeps at
       * least. */
      static constexpr double floor_fraction = 0.01;

      /**
       * Start with rule @p rule and Shi's distance @p full (m, positive).
       * The first step is detected with the floor (`motion`): a scene
       * whose first step moves further is detected again.
       */
      void
      initialize(const Rule rule, const double full);

      /**
       * The distance to detect the next step with, whose first attempt
       * has size @p dt (s).
       */
      double
      for_step(const double dt);

      /**
       * The least skin of the neighbour list (m, NeighbourList::detect()):
       * a quarter of Shi's distance with the rule `motion`, so that a list
       * is not built again every other step of a moving scene; none with
       * `scene` (the list's own skin, the distance itself, is Shi's).
       */
      double
      skin() const
      {
        return rule == Rule::motion ? 0.25 * full : 0.;
      }

      /** Whether the distance follows the motion (and accept() needs the
       * depth of the contacts). */
      bool
      follows_motion() const
      {
        return rule == Rule::motion;
      }

      /** The distance the present step was detected with. */
      double
      get() const
      {
        return distance;
      }

      /**
       * Whether the detection of this step covers an attempt whose
       * largest displacement increment is @p max_increment (m).
       */
      bool
      covers(const double max_increment) const;

      /**
       * An attempt moved @p max_increment (m), further than covers()
       * allows: the distance to detect the step again with, four times
       * the increment (so more than twice get()), at most Shi's.
       */
      double
      widen(const double max_increment);

      /** A step of size @p dt (s) was accepted with largest increment
       * @p max_increment (m), its contacts at most @p max_depth (m) deep
       * (ContactHandler::max_depth()). */
      void
      accept(const double dt,
             const double max_increment,
             const double max_depth);

      /** Detections of steps again, since the start. */
      unsigned int
      n_widenings() const
      {
        return widenings;
      }

      /** Write the distance's state to a checkpoint or read it (Archive). */
      template <class Archive>
      void
      serialize(Archive &ar)
      {
        ar &rule &full &distance &motion &last_dt &last_increment &last_depth
          &have_step &widenings;
      }

    private:
      Rule   rule     = Rule::scene;
      double full     = 0;
      double distance = 0;
      /// The part of the distance that covers the motion.
      double       motion         = 0;
      double       last_dt        = 0;
      double       last_increment = 0;
      double       last_depth     = 0;
      bool         have_step      = false;
      unsigned int widenings      = 0;
    };
  } // namespace contact
} // namespace ndda

#endif
