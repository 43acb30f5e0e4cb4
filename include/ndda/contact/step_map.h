// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_contact_step_map_h
#define ndda_contact_step_map_h

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
     * What one step of ContactHandler leaves for the next, looked up by
     * key: a vector
     * filled during end_step() and sorted once by finish(), then
     * searched by bisection. Unlike a hash map it allocates nothing per
     * entry, and its storage is kept from step to step. An entry added
     * twice holds its later value, as an assignment to a map would.
     */
    template <typename Value>
    class StepMap
    {
    public:
      void
      clear()
      {
        entries.clear();
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
      }

      /** The value under @p k, or null. */
      const Value *
      find(const ContactKey &k) const
      {
        const auto e = std::lower_bound(entries.begin(),
                                        entries.end(),
                                        k,
                                        [](const auto &a, const ContactKey &b) {
                                          return a.first < b;
                                        });
        return e != entries.end() && e->first == k ? &e->second : nullptr;
      }

      bool
      contains(const ContactKey &k) const
      {
        return find(k) != nullptr;
      }

    private:
      std::vector<std::pair<ContactKey, Value>> entries;
    };
  } // namespace contact
} // namespace ndda

#endif
