// SPDX-License-Identifier: GPL-3.0-or-later

#include <deal.II/base/thread_management.h>

#include <ndda/physics/supernodal_solve.h>

#include <algorithm>
#include <numeric>

namespace ndda
{
  namespace
  {
    /**
     * Below this many values of L the solve stays on one thread: the
     * tasks would cost more than they save.
     */
    constexpr double min_parallel_work = 2e5;

    /** Subtrees split until the busiest thread has at most this much
     * more than the mean. */
    constexpr double balance = 1.05;

    /** At most this many splits of the tree. */
    constexpr unsigned int max_splits = 256;
  } // namespace



  void
  SupernodalSolve::initialize(const Factor &factor, const unsigned int threads)
  {
    L         = factor;
    n_threads = std::max(1u, threads);
    subtree_first.clear();
    subtree_last.clear();
    subtree_thread.clear();
    y.resize(L.n);
    buffer.resize(n_threads);

    const long          nsuper = L.nsuper;
    std::vector<long>   supernode_of_column(L.n);
    std::vector<long>   parent(nsuper, -1), first(nsuper), count(nsuper, 1);
    std::vector<double> work(nsuper), subtree_work(nsuper);
    for (long s = 0; s < nsuper; ++s)
      for (long k = L.super[s]; k < L.super[s + 1]; ++k)
        supernode_of_column[k] = s;
    bool postordered = true;
    for (long s = 0; s < nsuper; ++s)
      {
        const long n_columns = L.super[s + 1] - L.super[s];
        const long n_rows    = L.pi[s + 1] - L.pi[s];
        work[s]              = double(n_columns) * n_rows;
        if (n_rows > n_columns)
          parent[s] = supernode_of_column[L.s[L.pi[s] + n_columns]];
        postordered = postordered && (parent[s] == -1 || parent[s] > s);
      }
    if (!postordered)
      return;
    std::iota(first.begin(), first.end(), 0);
    for (long s = 0; s < nsuper; ++s)
      {
        subtree_work[s] += work[s];
        if (parent[s] != -1)
          {
            first[parent[s]] = std::min(first[parent[s]], first[s]);
            count[parent[s]] += count[s];
            subtree_work[parent[s]] += subtree_work[s];
          }
      }
    // Every subtree a range of supernodes, as the two passes need.
    for (long s = 0; s < nsuper; ++s)
      if (count[s] != s - first[s] + 1)
        return;
    const double total = std::accumulate(work.begin(), work.end(), 0.);
    if (n_threads == 1 || total < min_parallel_work)
      return;

    std::vector<std::vector<long>> children(nsuper);
    std::vector<long>              candidates;
    for (long s = 0; s < nsuper; ++s)
      if (parent[s] == -1)
        candidates.push_back(s);
      else
        children[parent[s]].push_back(s);
    // Largest subtrees first onto the least loaded thread; split the
    // largest subtree (its root goes to the top) until that balances.
    std::vector<double> load;
    for (unsigned int split = 0;; ++split)
      {
        std::sort(candidates.begin(), candidates.end(), [&](long a, long b) {
          return subtree_work[a] > subtree_work[b] ||
                 (subtree_work[a] == subtree_work[b] && a < b);
        });
        load.assign(n_threads, 0.);
        subtree_thread.assign(candidates.size(), 0);
        double in_subtrees = 0;
        for (std::size_t i = 0; i < candidates.size(); ++i)
          {
            const auto least  = std::min_element(load.begin(), load.end());
            subtree_thread[i] = least - load.begin();
            *least += subtree_work[candidates[i]];
            in_subtrees += subtree_work[candidates[i]];
          }
        const double busiest = *std::max_element(load.begin(), load.end());
        if (busiest <= balance * in_subtrees / n_threads ||
            split == max_splits || children[candidates[0]].empty())
          break;
        const long largest = candidates[0];
        candidates.erase(candidates.begin());
        candidates.insert(candidates.end(),
                          children[largest].begin(),
                          children[largest].end());
      }
    // The subtrees in the order of their supernodes.
    std::vector<std::size_t> order(candidates.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return candidates[a] < candidates[b];
    });
    for (const std::size_t i : order)
      {
        subtree_first.push_back(first[candidates[i]]);
        subtree_last.push_back(candidates[i]);
      }
    std::vector<unsigned int> thread(subtree_thread.size());
    for (std::size_t j = 0; j < order.size(); ++j)
      thread[j] = subtree_thread[order[j]];
    subtree_thread = thread;
    outside.resize(subtree_first.size());
  }



  std::size_t
  SupernodalSolve::n_subtrees() const
  {
    return subtree_first.size();
  }



  void
  SupernodalSolve::forward(const long                            s,
                           const long                            rows_end,
                           std::vector<double>                  &e,
                           std::vector<std::pair<long, double>> *out) const
  {
    // The diagonal block L11 y1 = y1, then e = L21 y1 for the rows below,
    // subtracted from those rows (those at or beyond rows_end, outside
    // the running subtree, kept in out instead).
    const long    k1 = L.super[s], n_columns = L.super[s + 1] - k1;
    const long    n_rows = L.pi[s + 1] - L.pi[s];
    const long   *rows   = L.s + L.pi[s];
    const double *block  = L.x + L.px[s];
    double       *y1     = y.data() + k1;
    for (long j = 0; j < n_columns; ++j)
      {
        const double *column = block + j * n_rows;
        y1[j] /= column[j];
        const double yj = y1[j];
        for (long i = j + 1; i < n_columns; ++i)
          y1[i] -= column[i] * yj;
      }
    const long n_below = n_rows - n_columns;
    if (n_below == 0)
      return;
    e.assign(n_below, 0.);
    for (long j = 0; j < n_columns; ++j)
      {
        const double *column = block + j * n_rows + n_columns;
        const double  yj     = y1[j];
        for (long i = 0; i < n_below; ++i)
          e[i] += column[i] * yj;
      }
    const long *below = rows + n_columns;
    long        i     = 0;
    for (; i < n_below && below[i] < rows_end; ++i)
      y[below[i]] -= e[i];
    for (; i < n_below; ++i)
      out->emplace_back(below[i], e[i]);
  }



  void
  SupernodalSolve::backward(const long s, std::vector<double> &gathered) const
  {
    // L11^T y1 = y1 - L21^T y2, column by column from the last; the
    // rows below (y2) are final, gathered once.
    const long    k1 = L.super[s], n_columns = L.super[s + 1] - k1;
    const long    n_rows  = L.pi[s + 1] - L.pi[s];
    const long    n_below = n_rows - n_columns;
    const long   *below   = L.s + L.pi[s] + n_columns;
    const double *block   = L.x + L.px[s];
    double       *y1      = y.data() + k1;
    gathered.resize(n_below);
    for (long i = 0; i < n_below; ++i)
      gathered[i] = y[below[i]];
    for (long j = n_columns - 1; j >= 0; --j)
      {
        const double *column = block + j * n_rows;
        // Four partial sums in a fixed order: the same round-off every
        // time, without one chain of dependent additions.
        double        t[4]  = {0., 0., 0., 0.};
        const double *lower = column + n_columns;
        long          i     = 0;
        for (; i + 4 <= n_below; i += 4)
          for (unsigned int r = 0; r < 4; ++r)
            t[r] += lower[i + r] * gathered[i + r];
        for (; i < n_below; ++i)
          t[0] += lower[i] * gathered[i];
        for (long k = j + 1; k < n_columns; ++k)
          t[1] += column[k] * y1[k];
        y1[j] = (y1[j] - ((t[0] + t[1]) + (t[2] + t[3]))) / column[j];
      }
  }



  void
  SupernodalSolve::solve(double *x, const double *b) const
  {
    const long nsuper = L.nsuper, n_subtrees = subtree_first.size();
    for (long k = 0; k < L.n; ++k)
      y[k] = b[L.perm[k]];

    // Runs job(t) for every thread t, the first on this one.
    const auto on_threads = [this](const auto &job) {
      dealii::Threads::TaskGroup<void> tasks;
      for (unsigned int t = 1; t < n_threads; ++t)
        tasks += dealii::Threads::new_task([&job, t]() { job(t); });
      job(0);
      tasks.join_all();
    };

    // Forward: the subtrees, then the top with each subtree's rows
    // outside it in their place.
    if (n_subtrees > 0)
      on_threads([&](const unsigned int thread) {
        for (long i = 0; i < n_subtrees; ++i)
          if (subtree_thread[i] == thread)
            {
              outside[i].clear();
              const long end = L.super[subtree_last[i] + 1];
              for (long s = subtree_first[i]; s <= subtree_last[i]; ++s)
                forward(s, end, buffer[thread], &outside[i]);
            }
      });
    std::vector<double> &e    = buffer[0];
    long                 next = 0;
    for (long s = 0; s < nsuper;)
      if (next < n_subtrees && s == subtree_first[next])
        {
          for (const auto &[row, value] : outside[next])
            y[row] -= value;
          s = subtree_last[next] + 1;
          ++next;
        }
      else
        forward(s++, L.n, e, nullptr);

    // Backward: the top, from the root, then the subtrees.
    long last = n_subtrees - 1;
    for (long s = nsuper - 1; s >= 0;)
      if (last >= 0 && s == subtree_last[last])
        {
          s = subtree_first[last] - 1;
          --last;
        }
      else
        backward(s--, e);
    if (n_subtrees > 0)
      on_threads([&](const unsigned int thread) {
        for (long i = 0; i < n_subtrees; ++i)
          if (subtree_thread[i] == thread)
            for (long s = subtree_last[i]; s >= subtree_first[i]; --s)
              backward(s, buffer[thread]);
      });

    for (long k = 0; k < L.n; ++k)
      x[L.perm[k]] = y[k];
  }
} // namespace ndda
