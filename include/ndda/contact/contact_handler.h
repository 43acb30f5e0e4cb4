// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_contact_contact_handler_h
#define ndda_contact_contact_handler_h

#include <deal.II/base/array_view.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <deal.II/fe/fe.h>

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <ndda/contact/contact_detection.h>
#include <ndda/contact/contact_law.h>
#include <ndda/contact/contact_statistics.h>
#include <ndda/contact/edge_shapes.h>
#include <ndda/contact/step_map.h>
#include <ndda/mesh/boundary_edges.h>
#include <ndda/physics/dof_map.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <functional>
#include <iterator>
#include <tuple>
#include <utility>
#include <vector>

namespace ndda
{
  class BlockFrames;
  class OwnedCells;

  namespace contact
  {
    /**
     * The contacts of a scene: from the candidates of contact detection to
     * springs in the system matrix, and the open-close iteration's states,
     * carried from step to step.
     *
     * Every step:
     * 1. begin_step(): detect candidates on the geometry at the step's
     *    start, turn them into contacts (vertex-edge; vertex-vertex pairs
     *    with their potential reference edges, chapter 6; edge-edge as
     *    vertex-edge at the end point of the edge), and carry state,
     *    reference edge and anchor ratio over from the last step.
     * 2. open-close iteration: assemble() adds the springs of the present
     *    states; after each solve, update_states() classifies every
     *    contact from the solution and reports whether a state changed.
     *    restart_step() goes back to the states of the step's start (for
     *    a cut step).
     * 3. end_step(): keep states, anchors and energies for the next step.
     *
     * The springs act between the contact vertex and the material point of
     * the edge that the vertex projects on, evaluated with the element's
     * own shape functions at that point, so any FE_SimplexP degree works.
     * The normal gap is linearised as g = g0 + e_n . d, the shear
     * displacement as s = s0 + e_t . d, with e_n (e_t) the normal (tangent)
     * at the vertex minus the shape-function-weighted normal (tangent) at
     * the edge's nodes; doc/contact.md derives the kernels and compares
     * them with thesis 3.76-3.104.
     *
     * The handler owns the geometry: detection, the narrow phase, the
     * vertex-vertex resolution of chapter 6, the memory carried from step
     * to step, and the geometry of bonded joints. What a contact does once
     * it has an edge — its springs, its state after a solve, its bond and
     * its energy — is the contact law's (ContactLaw, ContactSettings::law;
     * "penalty Coulomb" unless the settings name another).
     *
     * @ingroup contact
     */
    class ContactHandler
    {
    public:
      /**
       * Set up for a mesh: its boundary edges, the friction coefficient of
       * each edge's side (tan of the joint friction angle of the edge's
       * material) and the dofs, through a read-only view of the finite
       * element space @p dofs (the element, the dofs of every cell and
       * vertex), which must outlive the handler's use. If @p settings has
       * no contact law, the handler uses "penalty Coulomb"
       * (default_contact_law).
       */
      void
      initialize(const std::vector<BoundaryEdge> &edges,
                 const std::vector<double>       &edge_friction,
                 const DofMap                    &dofs,
                 const ContactSettings           &settings);

      /**
       * After a crack: take over what @p old remembers from the last step
       * (states, anchors, bonds, open contacts) and its accumulated
       * energies. The mesh's old vertices keep their indices through a
       * crack, so the memory's keys stay valid; the vertex copies a crack
       * makes start without memory.
       */
      void
      carry_memory_from(const ContactHandler &old);

      /**
       * The blocks that are rigid or affine (@p reduced, by block index):
       * their faces stay straight, so that a vertex inside a straight face
       * (two collinear boundary edges) adds nothing that the face's
       * corners do not hold, and is not a contact vertex (doc/contact.md,
       * "Straight faces of rigid and affine blocks"). Its edges stay, for
       * the other blocks' vertices. Not where joints are bonded: a bonded
       * joint is tied at every vertex of its finer side.
       */
      void
      set_reduced_blocks(const std::vector<bool> &reduced);

      /** Split detection among @p cells' processes (after initialize()). */
      void
      set_owned_cells(const OwnedCells *cells);

      /** Change the normal stiffness (automatic penalty). */
      void
      set_normal_stiffness(const double k);

      const ContactSettings &
      get_settings() const
      {
        return settings;
      }

      /**
       * Detect and set up the contacts of a step on the @p vertices at the
       * step's start within @p threshold, the neighbour list's skin at
       * least @p min_skin. Called again within a step (a widened distance,
       * a crack, a promoted block), it starts anew from the same memory.
       */
      void
      begin_step(const std::vector<Point<2>> &vertices,
                 const double                 threshold,
                 const double                 min_skin = 0.);

      /**
       * Would begin_step() within @p threshold find more candidates than
       * the step's (a larger distance finds a superset)?
       */
      bool
      finds_more(const std::vector<Point<2>> &vertices,
                 const double                 threshold,
                 const double                 min_skin = 0.);

      /** Back to the states of the step's start (the step is retried). */
      void
      restart_step();

      /**
       * The (vertex, cell) pairs a spring of this step may couple: the
       * sparsity pattern must hold the couplings of the vertex's dofs with
       * the cell's dofs. Sorted and unique.
       */
      const std::vector<std::pair<unsigned int, unsigned int>> &
      get_couplings() const
      {
        return couplings;
      }

      /** True if some contact has a spring in its present state. */
      bool
      has_springs() const;

      /**
       * The blocks' frames in which the linear system is solved
       * (referenced; nullptr: the global frame): assemble() turns the
       * springs into them.
       */
      void
      set_frames(const BlockFrames *frames)
      {
        this->frames = frames;
      }

      /**
       * Add the springs of the present states through @p add, one dense
       * block per contact with the contact's index as its number, in the
       * blocks' frames (Q^T S Q, see set_frames()), and their forces at
       * d = 0 to @p rhs, in global components. A contact whose state,
       * option and scale are those of its last assembly in this step has
       * the same block: @p add is asked to add the block it kept (a null
       * block), and the law gives only the forces.
       */
      void
      assemble(
        const std::function<
          bool(const unsigned int,
               const dealii::ArrayView<const dealii::types::global_dof_index> &,
               const dealii::FullMatrix<double> *)> &add,
        dealii::Vector<double>                      &rhs) const;

      /**
       * For the Newmark integrator, which averages the forces at the
       * step's start and end through the inertia force M a0 of the last
       * step: the correction to M a0 that replaces the contact forces it
       * holds (those at the last step's end) by the start forces of the
       * contacts that are closed at both ends of this step. Contacts that
       * open then release their spring energy without the work of half
       * their start force over the opening gap, which would otherwise add
       * energy at every opening (doc/contact.md).
       */
      void
      newmark_correction(dealii::Vector<double> &force) const;

      /**
       * The forces at the step's start (on its start geometry) of the
       * contacts that are closed at both ends of the step.
       */
      void
      start_forces(dealii::Vector<double> &force) const;

      /** Classify every contact from the solution @p d of the last solve
       * (thesis's open-close criteria, Coulomb limit, vertex-vertex
       * resolution); true if any state changed: another solve is needed. */
      bool
      update_states(const dealii::Vector<double> &d);

      /** If a force of the law lagged behind the solve @p d (ContactLaw::
       * force_lags()), record the closed contacts' gaps of @p d as their
       * solved_gap and return true: solve again in the same states. */
      bool
      settle_lagging_forces(const dealii::Vector<double> &d);

      /**
       * Whether the changes of the last update_states() were all one-way:
       * every contact that changed went to a state (and sliding direction)
       * it has not had before in this step (a vertex-vertex pair's state
       * counts whichever edge it is on, so a pair that changes its edge
       * in the same state is not one-way). Each one-way change sets one of
       * a contact's few state bits, so iterations whose changes are all
       * one-way cannot cycle and end (OpenCloseSolver lets them go on past
       * the limit).
       */
      bool
      last_changes_one_way() const
      {
        return one_way;
      }

      /** Largest penetration (m) at the end of the step with increment
       * @p d, over the closed contacts. */
      double
      max_penetration(const dealii::Vector<double> &d) const;

      /** Largest depth (m) of a vertex behind its contact's edge at the
       * end of the step with increment @p d, offsets included: what the
       * next step's detection distance must reach (DetectionDistance). */
      double
      max_depth(const dealii::Vector<double> &d) const;

      /** Accept the step's solution @p d: energies, anchors, transfer. */
      void
      end_step(const dealii::Vector<double> &d);

      /** Count one open-close iteration (for the statistics). */
      void
      count_iteration()
      {
        ++statistics.n_iterations;
      }

      const ContactStatistics &
      get_statistics() const
      {
        return statistics;
      }

      /**
       * The contact forces on the nodes at the end of the last step
       * (global components; empty before the first step ends).
       */
      const dealii::Vector<double> &
      end_forces() const
      {
        return end_force;
      }

      /**
       * The contact forces on the nodes at the end of the step being
       * solved, with the settled increment @p d (as end_step() will find
       * them; nothing is committed).
       */
      void
      trial_end_forces(const dealii::Vector<double> &d,
                       dealii::Vector<double>       &force) const;

      /** Write what the contacts carry from step to step (memory, normal
       * stiffness, edge lengths, statistics, end forces) to a checkpoint,
       * or read it (Archive); the rest is set up from the mesh. */
      template <class Archive>
      void
      serialize(Archive &ar)
      {
        ar &settings.normal_stiffness &block_edge_length &memory &open_last_step
          &statistics &first_step &one_way &end_force;
      }

      /** Forget the neighbour list: the next step builds it (a resume). */
      void
      forget_neighbours()
      {
        neighbours.clear();
      }

    private:
      /**
       * A contact: a vertex-edge pair or a vertex-vertex pair. Its present
       * state, anchor, sliding direction, friction and bond length are the
       * ContactState the contact law sees.
       */
      struct ContactPair : ContactState
      {
        /// Potential (vertex, edge) pairs: one for a vertex-edge contact,
        /// the edges at either vertex for a vertex-vertex pair.
        boost::container::small_vector<Option, 1> options;
        /// The chosen option, or invalid while a vertex-vertex pair is
        /// unresolved.
        unsigned int chosen = invalid;
        /// The two vertices of a vertex-vertex pair.
        unsigned int vertex_a = invalid, vertex_b = invalid;

        /// The state at the step's start, and its chosen option.
        ContactState start;
        unsigned int start_chosen = invalid;
        /// Changes between open and closed in this step's iteration.
        unsigned int flips = 0;
        /// Changes of a closed contact between locked and the two sliding
        /// directions in this step's iteration.
        unsigned int shear_flips = 0;
        /// The (state, sliding direction) pairs the contact has had in
        /// this step's iteration, one bit each (visit()).
        std::uint16_t visited = 0;

        /// Mark the present (state, sliding direction) as visited in this
        /// step; returns whether it had been visited before.
        bool
        visit()
        {
          const std::uint16_t bit =
            1u << (3 * static_cast<unsigned int>(state) + (sign + 1));
          const bool before = (visited & bit) != 0;
          visited |= bit;
          return before;
        }
        /// Newmark: the fraction of the step's end force (closing) or start
        /// force (opening) the integrator uses, see update_scale().
        double scale = 1;
        /// Penetration (m, <= 0) the contact already had when it first
        /// closed; the normal spring acts on the gap beyond it (the chosen
        /// option's gap has it subtracted), so that a contact that appears
        /// inside an overlap does not add the overlap's spring energy.
        double offset = 0;
        /// The joint's cohesion and tension hold this contact (it touched
        /// at the start of the run and has not broken since).
        bool bonded       = false;
        bool start_bonded = false;
        /// A contact on a bonded joint from the other side: a bonded joint
        /// is tied from one side only (doc/contact.md, "Bonded joints"),
        /// this contact stays open until the bonds next to it break.
        bool shadowed = false;
      };

      /** What is carried from one step to the next, per contact key. */
      struct Memory
      {
        State  state;
        double anchor;
        int    sign;
        double offset;
        bool   bonded;

        template <class Archive>
        void
        serialize(Archive &ar)
        {
          ar &state &anchor &sign &offset &bonded;
        }
      };

      /** A (vertex, boundary edge) pair. */
      using VertexEdge = std::pair<unsigned int, unsigned int>;

      static constexpr unsigned int invalid = static_cast<unsigned int>(-1);

      /** A vertex and the two vertices of an edge, or two vertices. */
      using Key = ContactKey;

      /** Key of a (vertex, edge) pair that survives renumbered edges. */
      Key
      key(const unsigned int vertex, const unsigned int edge) const
      {
        return {vertex, edges[edge].v0, edges[edge].v1};
      }

      /**
       * @name Narrow phase (source/contact/narrow_phase.cc): from the
       * candidates of detect() to the contacts of a step.
       */
      /** @{ */

      /** The option of @p vertex against @p edge on the @p vertices. */
      Option
      make_option(const std::vector<Point<2>> &vertices,
                  const unsigned int           vertex,
                  const unsigned int           edge) const;

      /**
       * Is @p vertex one of the nodes of the cell of @p edge (the third
       * vertex of a thin triangle, or a mesh neighbour)?
       */
      bool
      in_cell(const unsigned int vertex, const unsigned int edge) const;

      /**
       * The outward unit normal of every boundary edge and their sum at
       * every vertex, on the @p vertices of the step: made once at the
       * start of the narrow phase, for facing() and the corner tests; and
       * which vertices are passive (set_reduced_blocks()).
       */
      void
      compute_normals(const std::vector<Point<2>> &vertices);

      /**
       * Can @p vertex touch @p edge: do the outward normal at the vertex
       * (the mean of its edges' normals) and the edge's normal point
       * against each other? This rules out the other vertices of the same
       * straight side, every vertex of a convex block against its own
       * edges, and the far face of a thin block. On the normals of
       * compute_normals().
       */
      bool
      facing(const unsigned int vertex, const unsigned int edge) const;

      /**
       * Is there a state to carry over to @p vertex on @p edge (see
       * transfer()): the pair's own, or that of the vertex on a
       * neighbouring edge across a straight vertex?
       */
      bool
      remembered(const std::vector<Point<2>> &vertices,
                 const unsigned int           vertex,
                 const unsigned int           edge) const;

      /**
       * The vertex-edge contacts of a step, sorted by vertex, then edge:
       * the vertex_edge candidates of each vertex that can touch their
       * edge, one of two at a convex corner (see touched_edges()), except
       * a face's straight vertex on the edges of a convex corner that
       * touches the face (doc/contact.md, item 2).
       */
      std::vector<VertexEdge>
      vertex_edge_pairs(const std::vector<Point<2>>  &vertices,
                        const std::vector<Candidate> &candidates) const;

      /**
       * Of the vertex_edge candidates of one vertex, [@p first, @p last),
       * those that can be contacts: not on an edge of the vertex's own
       * cell, facing, and not new and deep inside the other body (the far
       * face of a thin block). A vertex near a convex (or straight) corner
       * of a boundary may project into both edges there; it then touches
       * one of them: the remembered one, else the one it is farther
       * outside of. They are appended to @p touched.
       */
      void
      touched_edges(const std::vector<Point<2>>           &vertices,
                    std::vector<Candidate>::const_iterator first,
                    std::vector<Candidate>::const_iterator last,
                    std::vector<VertexEdge>               &touched) const;

      /** Add a vertex-edge contact for each of @p vertex_edge. */
      void
      add_vertex_edge_contacts(const std::vector<Point<2>>   &vertices,
                               const std::vector<VertexEdge> &vertex_edge);

      /**
       * Does @p vertex have a vertex-edge contact, among the sorted
       * @p vertex_edge (the step's, indexed in vertex_edge_start), on an
       * edge at @p corner?
       */
      bool
      has_vertex_edge_at(const std::vector<VertexEdge> &vertex_edge,
                         const unsigned int             vertex,
                         const unsigned int             corner) const;

      /** A pair of vertices that may touch, and whether faces at the two
       * lie on each other (faces_meet()). */
      struct VertexPair
      {
        unsigned int a, b;
        bool         faces_meet;
      };

      /**
       * The vertex pairs (smaller index first, sorted) of the vertex_vertex
       * candidates: a vertex and the end point of the edge closest to it,
       * unless the vertex belongs to the edge's cell (for every candidate
       * of the pair), the two vertices are the ends of one boundary edge,
       * either of the two touches an edge at the other (the vertex-edge
       * contact holds the pair; not where faces at the two lie on each
       * other, faces_meet(), and one of the two has no contact on the
       * other's faces yet), or either is nearer to the other's block
       * elsewhere. Each of these is decided by candidates nearer than the
       * pair, so the pairs do not depend on the detection distance.
       */
      std::vector<VertexPair>
      vertex_vertex_pairs(const std::vector<Point<2>>   &vertices,
                          const std::vector<Candidate>  &candidates,
                          const std::vector<VertexEdge> &vertex_edge) const;

      /**
       * Has @p vertex a facing candidate, not in its own cell, on an edge of
       * the block of @p other that does not end at @p other, nearer than
       * @p other (found at any distance that finds the pair)? Among the
       * step's @p candidates, indexed in candidate_start.
       */
      bool
      nearer_elsewhere(const std::vector<Point<2>>  &vertices,
                       const std::vector<Candidate> &candidates,
                       const unsigned int            vertex,
                       const unsigned int            other) const;

      /**
       * Add the contacts of the vertex pairs of vertex_vertex_pairs():
       * two edge-edge contacts where faces at the two vertices overlap,
       * else a vertex-vertex contact.
       */
      void
      add_vertex_vertex_contacts(const std::vector<Point<2>>   &vertices,
                                 const std::vector<Candidate>  &candidates,
                                 const std::vector<VertexEdge> &vertex_edge);

      /**
       * Is edge @p e at vertex @p b a face that @p a faces and that lies on
       * a face at @p a (an edge at @p a that leaves @p a in the same
       * direction as @p e leaves @p b, and faces @p b)?
       */
      bool
      parallel_faces(const std::vector<Point<2>> &vertices,
                     const unsigned int           a,
                     const unsigned int           b,
                     const unsigned int           e) const;

      /** Do faces at @p a and @p b lie on each other (parallel_faces())? */
      bool
      faces_meet(const std::vector<Point<2>> &vertices,
                 const unsigned int           a,
                 const unsigned int           b) const;

      /**
       * The contact of vertex @p v of a vertex pair on a face at vertex
       * @p w: on the edge at @p w that @p v projects farthest into, among
       * those that lie on a face at @p v (parallel_faces()), or, if @p w is
       * passive (set_reduced_blocks()), that @p v faces; none if @p v
       * already touches an edge at @p w, lies beyond the faces, or is new
       * and deep behind the face (a thin body's other side).
       *
       * Edge-edge (faces at the two vertices lie on each other) is
       * nothing indeterminate: each vertex touches the other's face there,
       * one such contact for each. Both are kept, also where one of them
       * is already a vertex-edge contact, so that the pair has the same
       * two springs whichever vertex rounding puts exactly at the other's
       * end, and when the corners move apart the one whose vertex slides
       * onto the other's edge goes on with its state, and no contact
       * appears already compressed. A vertex at a passive vertex is a
       * vertex on a straight face: one contact, of the vertex.
       */
      void
      add_face_contact(const std::vector<Point<2>>   &vertices,
                       const std::vector<VertexEdge> &vertex_edge,
                       const unsigned int             v,
                       const unsigned int             w);

      /**
       * A vertex-vertex contact of @p a and @p b with the facing edges at
       * either vertex as its options (thesis chapter 6), unless it is new
       * and one vertex starts deep inside the other's corner (the two lie
       * on opposite sides of a thin body).
       */
      void
      add_vertex_vertex_contact(const std::vector<Point<2>> &vertices,
                                const unsigned int           a,
                                const unsigned int           b);
      /** @} */

      /**
       * @name Transfer (source/contact/transfer.cc): what a contact carries
       * from the last step.
       */
      /** @{ */

      /** Carry the memory of the last step over to contact @p c. */
      void
      transfer(ContactPair &c, const std::vector<Point<2>> &vertices) const;

      /**
       * The state, option and anchor of the last step's end for contact
       * @p c, from its own memory or (vertex-edge) from the memory of its
       * vertex on a neighbouring edge it has slid over from.
       */
      void
      recall(ContactPair &c, const std::vector<Point<2>> &vertices) const;

      /**
       * A neighbouring edge of @p edge, across a (nearly) straight vertex,
       * on which @p vertex has a state remembered from the last step (it
       * has slid over from there), or invalid.
       */
      unsigned int
      straight_neighbour_in_memory(const std::vector<Point<2>> &vertices,
                                   const unsigned int           vertex,
                                   const unsigned int           edge) const;
      /** @} */

      /**
       * @name Bonded joints (source/contact/bonded_joints.cc): the
       * geometry of the joints that the contact law bonds.
       */
      /** @{ */

      /**
       * The mean boundary edge length of every block on the @p vertices,
       * into block_edge_length (on the first step's geometry: it decides
       * which side ties a bonded joint).
       */
      void
      measure_block_edges(const std::vector<Point<2>> &vertices);

      /**
       * Is a contact of @p vertex on @p edge the side a bonded joint is
       * tied from: the vertex's block has the finer boundary (shorter mean
       * boundary edge; the smaller block index if equal; within one block,
       * the smaller vertex index)? The finer side has more contacts to
       * share the joint's forces.
       */
      bool
      bonding_side(const unsigned int vertex, const unsigned int edge) const;

      /**
       * The length of joint a bonded vertex-edge contact of @p vertex on
       * @p edge stands for: of each boundary edge at the vertex that runs
       * along @p edge (antiparallel within 10 degrees), the part that lies
       * on @p edge and the straight continuation of the other side's
       * boundary beyond it; half of it if the edge's other end lies on the
       * joint as well (and so has a contact of its own), all of it
       * otherwise. The lengths of the contacts on a joint add up to the
       * joint's length.
       */
      double
      bond_length(const std::vector<Point<2>> &vertices,
                  const unsigned int           vertex,
                  const unsigned int           edge) const;

      /**
       * A bonded joint is tied from one side: the contacts from the other
       * side on an edge whose end vertex is bonded to the contact vertex's
       * block are shadowed, and stay open.
       */
      void
      shadow_bonded_joints();
      /** @} */

      /**
       * @name Vertex-vertex resolution (source/contact/vertex_vertex.cc),
       * thesis chapter 6.
       */
      /** @{ */

      /**
       * Resolve an unresolved vertex-vertex pair @p c after the solution
       * @p d: choose its reference edge once a vertex has entered the
       * other's corner, or put it on the temporary vertex spring. Returns
       * true if it changed.
       */
      bool
      resolve_pair(ContactPair &c, const dealii::Vector<double> &d);

      /**
       * The options of pair @p c whose vertex has entered the other's
       * corner under @p d: it ends behind the lines of both edges there,
       * within their lengths.
       */
      std::vector<unsigned int>
      entered_options(const ContactPair            &c,
                      const dealii::Vector<double> &d) const;

      /** Choose the entrance edge of a penetrating vertex-vertex pair among
       * the options @p inside of the vertices that entered; invalid for
       * genuine indeterminacy (revised method). */
      unsigned int
      entrance_option(const ContactPair               &c,
                      const std::vector<unsigned int> &inside,
                      const dealii::Vector<double>    &d) const;

      /** The option a temporary vertex spring resolves to (6.2), or
       * invalid if the motion is symmetric. */
      unsigned int
      sliding_option(const ContactPair            &c,
                     const dealii::Vector<double> &d) const;
      /** @} */

      /**
       * Classify a resolved contact @p c from the solution @p d: its bond,
       * else the contact law; returns true if its state changed.
       */
      bool
      update_state(ContactPair &c, const dealii::Vector<double> &d);

      /** Update the scale of a contact that closes or opens within the
       * step; true if it changed noticeably. */
      bool
      update_scale(ContactPair &c, const dealii::Vector<double> &d);

      /**
       * end_step() for a temporary vertex spring: its memory, energy and
       * force at the step's end.
       */
      void
      end_vertex_spring(const ContactPair &c, const dealii::Vector<double> &d);

      /**
       * Add the force of @p c at the end of the step with increment @p d
       * (a temporary vertex spring's or a closed contact's; none for an
       * open one) to @p force.
       */
      void
      add_end_force(const ContactPair            &c,
                    const dealii::Vector<double> &d,
                    dealii::Vector<double>       &force) const;

      /**
       * end_step() for a closed contact: its memory, energy, force at the
       * step's end and statistics.
       */
      void
      end_closed_contact(const ContactPair &c, const dealii::Vector<double> &d);

      ContactSettings                        settings;
      const DofMap                          *dofs   = nullptr;
      const BlockFrames                     *frames = nullptr;
      std::vector<BoundaryEdge>              edges;
      std::vector<double>                    edge_friction;
      std::vector<double>                    vertex_friction;
      std::vector<std::vector<unsigned int>> edges_at_vertex;
      /// The shape functions along the edges, for the options.
      EdgeShapes edge_shapes;
      /// The outward unit normals of the boundary edges, and their sums
      /// at the vertices, on the vertices of the step (compute_normals()).
      std::vector<Tensor<1, 2>> edge_normal;
      std::vector<Tensor<1, 2>> vertex_normal;
      /// The rigid and affine blocks (set_reduced_blocks()), and the
      /// vertices of the step that are not contact vertices: inside a
      /// straight face of such a block (compute_normals()).
      std::vector<bool> reduced_block;
      std::vector<bool> passive;
      /// Where the entries of every vertex begin in the step's candidates
      /// and vertex-edge pairs, both sorted by vertex (begin_step()), and
      /// end: at the next vertex's start.
      std::vector<unsigned int> candidate_start;
      std::vector<unsigned int> vertex_edge_start;
      /// Detection's broad phase, kept while the vertices move little.
      NeighbourList     neighbours;
      const OwnedCells *owned_cells = nullptr; ///< set_owned_cells()
      /// Mean boundary edge length of every block (m).
      std::vector<double>      block_edge_length;
      std::vector<ContactPair> contacts;
      /// What each contact's spring block was last assembled from in this
      /// step (assemble(); emptied by begin_step() and restart_step()).
      struct Assembled
      {
        bool         valid = false;
        ContactState state;
        unsigned int chosen = invalid;
        double       scale  = 0;
        bool         bonded = false;
      };
      mutable std::vector<Assembled>                     assembled;
      std::vector<std::pair<unsigned int, unsigned int>> couplings;
      /// What each contact of the last step left (looked up by key only).
      StepMap<Memory> memory;
      /// Vertex-edge contacts that ended the last step open: one that
      /// touches at the start of the next step starts it open too.
      StepMap<bool>     open_last_step;
      ContactStatistics statistics;
      /// No step accepted yet: contacts that touch now are bonded.
      bool first_step = true;
      /// See last_changes_one_way().
      bool one_way = true;
      /// Forces of all springs at the end of the last accepted step.
      dealii::Vector<double> end_force;
      /// Scratch of end_step(): the forces applied over the step.
      dealii::Vector<double> applied;
    };
  } // namespace contact
} // namespace ndda

#endif
