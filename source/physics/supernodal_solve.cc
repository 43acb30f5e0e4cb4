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
    // Four columns at a time: each row still takes the columns' terms
    // one after the other, in column order (the same round-off as one
    // column at a time), and is loaded and stored once per four.
    long j = 0;
    for (; j + 4 <= n_columns; j += 4)
      {
        const double *c0 = block + j * n_rows, *c1 = c0 + n_rows,
                     *c2 = c1 + n_rows, *c3 = c2 + n_rows;
        // The 4 x 4 triangle on the diagonal, column by column.
        for (long k = 0; k < 4; ++k)
          {
            const double *column = c0 + k * n_rows;
            y1[j + k] /= column[j + k];
            for (long i = j + k + 1; i < j + 4; ++i)
              y1[i] -= column[i] * y1[j + k];
          }
        const double y_0 = y1[j], y_1 = y1[j + 1], y_2 = y1[j + 2],
                     y_3 = y1[j + 3];
        for (long i = j + 4; i < n_columns; ++i)
          {
            double t = y1[i];
            t -= c0[i] * y_0;
            t -= c1[i] * y_1;
            t -= c2[i] * y_2;
            t -= c3[i] * y_3;
            y1[i] = t;
          }
      }
    for (; j < n_columns; ++j)
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
    double *const sum = e.data();
    j                 = 0;
    for (; j + 4 <= n_columns; j += 4)
      {
        const double *c0 = block + j * n_rows + n_columns, *c1 = c0 + n_rows,
                     *c2 = c1 + n_rows, *c3 = c2 + n_rows;
        const double y_0 = y1[j], y_1 = y1[j + 1], y_2 = y1[j + 2],
                     y_3 = y1[j + 3];
        for (long i = 0; i < n_below; ++i)
          {
            double t = sum[i];
            t += c0[i] * y_0;
            t += c1[i] * y_1;
            t += c2[i] * y_2;
            t += c3[i] * y_3;
            sum[i] = t;
          }
      }
    for (; j < n_columns; ++j)
      {
        const double *column = block + j * n_rows + n_columns;
        const double  yj     = y1[j];
        for (long i = 0; i < n_below; ++i)
          sum[i] += column[i] * yj;
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
    const double *g = gathered.data();
    // Each column's sum over the rows below in four partial sums, in a
    // fixed order: the same round-off every time, without one chain of
    // dependent additions. Those sums do not depend on y1, so four
    // columns take them in one pass over the gathered values; then each
    // column, from the last, adds its terms in the diagonal block and is
    // solved for.
    const long n_whole = n_below - n_below % 4;
    const auto finish  = [&](const long j, double *t) {
      const double *column = block + j * n_rows;
      const double *lower  = column + n_columns;
      for (long i = n_whole; i < n_below; ++i)
        t[0] += lower[i] * g[i];
      for (long k = j + 1; k < n_columns; ++k)
        t[1] += column[k] * y1[k];
      y1[j] = (y1[j] - ((t[0] + t[1]) + (t[2] + t[3]))) / column[j];
    };
    long j = n_columns - 1;
    for (; j >= 3; j -= 4)
      {
        // Columns j, j - 1, j - 2, j - 3.
        const double *l0 = block + j * n_rows + n_columns, *l1 = l0 - n_rows,
                     *l2 = l1 - n_rows, *l3 = l2 - n_rows;
        double t[4][4] = {};
        for (long i = 0; i < n_whole; i += 4)
          for (unsigned int r = 0; r < 4; ++r)
            {
              const double gi = g[i + r];
              t[0][r] += l0[i + r] * gi;
              t[1][r] += l1[i + r] * gi;
              t[2][r] += l2[i + r] * gi;
              t[3][r] += l3[i + r] * gi;
            }
        for (unsigned int k = 0; k < 4; ++k)
          finish(j - k, t[k]);
      }
    for (; j >= 0; --j)
      {
        const double *lower = block + j * n_rows + n_columns;
        double        t[4]  = {0., 0., 0., 0.};
        for (long i = 0; i < n_whole; i += 4)
          for (unsigned int r = 0; r < 4; ++r)
            t[r] += lower[i + r] * g[i + r];
        finish(j, t);
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
