// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_contact_step_map_h
#define ndda_contact_step_map_h

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <iterator>
#include <tuple>
#include <utility>
#include <vector>

namespace ndda
{
  namespace contact
  {
    /**
     * The key of a contact's memory: a vertex and the two vertices of an
     * edge (a key that survives renumbered edges), or two vertices and
     * an invalid index (a vertex-vertex pair).
     */
    using ContactKey = std::tuple<unsigned int, unsigned int, unsigned int>;

    /**
     * Where the entries of every vertex (of @p n_vertices) begin in
     * @p list, sorted by the vertex @p vertex_of gives an entry: they are
     * @p start[v] to @p start[v + 1], found without a search.
     */
    template <typename List, typename VertexOf>
    void
    index_by_vertex(const unsigned int         n_vertices,
                    const List                &list,
                    const VertexOf            &vertex_of,
                    std::vector<unsigned int> &start)
    {
      Assert(std::is_sorted(list.begin(),
                            list.end(),
                            [&](const auto &a, const auto &b) {
                              return vertex_of(a) < vertex_of(b);
                            }),
             dealii::ExcMessage("index_by_vertex(): the list is not sorted."));
      start.assign(n_vertices + 1, 0);
      for (const auto &entry : list)
        ++start[vertex_of(entry) + 1];
      for (unsigned int v = 0; v < n_vertices; ++v)
        start[v + 1] += start[v];
    }

    /**
     * What one step of ContactHandler leaves for the next, looked up by
     * key: a vector filled during end_step() and sorted once by finish(),
     * which also notes where the entries of every first index (a vertex)
     * begin; a key is then found among its vertex's few entries. Unlike a
     * hash map it allocates nothing per entry, and its storage is kept
     * from step to step. An entry added twice holds its later value, as
     * an assignment to a map would.
     */
    template <typename Value>
    class StepMap
    {
    public:
      void
      clear()
      {
        entries.clear();
        start.clear();
      }

      void
      add(const ContactKey &k, const Value &value)
      {
        entries.emplace_back(k, value);
      }

      /** Sort the entries added; keep the last of equal keys. */
      void
      finish()
      {
        std::stable_sort(entries.begin(),
                         entries.end(),
                         [](const auto &a, const auto &b) {
                           return a.first < b.first;
                         });
        auto last = entries.begin();
        for (auto e = entries.begin(); e != entries.end(); ++e)
          if (std::next(e) == entries.end() || std::next(e)->first != e->first)
            *last++ = *e;
        entries.erase(last, entries.end());
        index_by_vertex(
          entries.empty() ? 0 : std::get<0>(entries.back().first) + 1,
          entries,
          [](const auto &e) { return std::get<0>(e.first); },
          start);
      }

      /** The value under @p k, or null. */
      const Value *
      find(const ContactKey &k) const
      {
        const unsigned int v = std::get<0>(k);
        if (start.empty() || v >= start.size() - 1)
          return nullptr;
        for (unsigned int i = start[v]; i < start[v + 1]; ++i)
          if (entries[i].first == k)
            return &entries[i].second;
        return nullptr;
      }

      bool
      contains(const ContactKey &k) const
      {
        return find(k) != nullptr;
      }

      template <class Archive>
      void
      serialize(Archive &ar)
      {
        ar &entries &start;
      }

    private:
      std::vector<std::pair<ContactKey, Value>> entries;
      /// The entries of first index v are [start[v], start[v + 1]).
      std::vector<unsigned int> start;
    };
  } // namespace contact
} // namespace ndda

#endif
