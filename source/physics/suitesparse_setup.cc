// SPDX-License-Identifier: GPL-3.0-or-later
#include <ndda/physics/suitesparse_setup.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <malloc.h>
#include <mutex>
#include <omp.h>
#include <string>
#include <suitesparse/SuiteSparse_config.h>
#include <sys/mman.h>
#include <unordered_map>

namespace ndda
{
  namespace
  {
    constexpr std::size_t huge_page = std::size_t(2) << 20;

    std::size_t
    round_up(const std::size_t size, const std::size_t to)
    {
      return (size + to - 1) / to * to;
    }
  } // namespace



  void *
  map_huge_pages(const std::size_t size)
  {
    // Over-map by one huge page and cut the ends off, so that the block
    // starts on a 2 MB boundary and all of it can be huge pages.
    const std::size_t length = round_up(size, huge_page);
    void *const       mapped = mmap(nullptr,
                              length + huge_page,
                              PROT_READ | PROT_WRITE,
                              MAP_PRIVATE | MAP_ANONYMOUS,
                              -1,
                              0);
    if (mapped == MAP_FAILED)
      return nullptr;
    const auto address = reinterpret_cast<std::uintptr_t>(mapped);
    const auto first   = round_up(address, huge_page);
    if (first > address)
      munmap(mapped, first - address);
    if (address + huge_page > first)
      munmap(reinterpret_cast<void *>(first + length),
             address + huge_page - first);
#ifdef MADV_HUGEPAGE
    // A kernel without transparent huge pages says EINVAL; the memory
    // works the same either way.
    (void)madvise(reinterpret_cast<void *>(first), length, MADV_HUGEPAGE);
#endif
    return reinterpret_cast<void *>(first);
  }



  void
  unmap_huge_pages(void *const block, const std::size_t size)
  {
    if (block != nullptr)
      munmap(block, round_up(size, huge_page));
  }



  namespace
  {
    /**
     * SuiteSparse's allocator: blocks of at least huge_page_threshold()
     * bytes are mappings of their own in huge pages, remembered here with
     * their sizes; all others come from malloc(). A block that is not
     * here is malloc()'s, also one allocated before set_up_suitesparse().
     */
    struct HugeBlocks
    {
      std::mutex                              mutex;
      std::unordered_map<void *, std::size_t> size_of;

      /** Remember @p block as a mapping of @p size bytes. */
      void
      set(void *const block, const std::size_t size)
      {
        std::lock_guard<std::mutex> lock(mutex);
        size_of[block] = size;
      }

      void *
      add(const std::size_t size)
      {
        void *const block = map_huge_pages(size);
        if (block != nullptr)
          set(block, size);
        return block;
      }

      /** Forget @p block; its size, or 0 if it is malloc()'s. */
      std::size_t
      remove(void *const block)
      {
        std::lock_guard<std::mutex> lock(mutex);
        const auto                  found = size_of.find(block);
        if (found == size_of.end())
          return 0;
        const std::size_t size = found->second;
        size_of.erase(found);
        return size;
      }
    };

    HugeBlocks &
    huge_blocks()
    {
      // Never destroyed: SuiteSparse objects may be freed at exit.
      static HugeBlocks *const blocks = new HugeBlocks;
      return *blocks;
    }

    void *
    allocate(const std::size_t size)
    {
      return size >= huge_page_threshold() ? huge_blocks().add(size) :
                                             std::malloc(size);
    }

    void *
    allocate_zeros(const std::size_t n, const std::size_t size)
    {
      // Fresh mappings are zero.
      if (size != 0 && n <= SIZE_MAX / size &&
          n * size >= huge_page_threshold())
        return huge_blocks().add(n * size);
      return std::calloc(n, size);
    }

    void
    release(void *const block)
    {
      if (const std::size_t size = huge_blocks().remove(block); size > 0)
        unmap_huge_pages(block, size);
      else
        std::free(block);
    }

    void *
    reallocate(void *const old_block, const std::size_t size)
    {
      if (old_block == nullptr)
        return allocate(size);
      const std::size_t old_size = huge_blocks().remove(old_block);
      if (old_size == 0 && size < huge_page_threshold())
        return std::realloc(old_block, size);
      if (old_size > 0 && size >= huge_page_threshold() &&
          round_up(size, huge_page) <= round_up(old_size, huge_page))
        {
          // Shrink in place: give the tail back.
          const std::size_t keep = round_up(size, huge_page);
          if (keep < round_up(old_size, huge_page))
            munmap(static_cast<char *>(old_block) + keep,
                   round_up(old_size, huge_page) - keep);
          huge_blocks().set(old_block, size);
          return old_block;
        }
      if (old_size > 0 &&
          round_up(size, huge_page) > round_up(old_size, huge_page))
        {
          // Grow a mapping: move its pages to the start of a new one. The
          // kernel moves their page tables; nothing is copied, and only
          // the new tail's pages are cleared when first touched (a copy
          // would clear every page of the new block and then write it).
          void *const block = map_huge_pages(size);
          if (block != nullptr)
            {
              const std::size_t old_length = round_up(old_size, huge_page);
              if (mremap(old_block,
                         old_length,
                         old_length,
                         MREMAP_MAYMOVE | MREMAP_FIXED,
                         block) != MAP_FAILED)
                {
                  huge_blocks().set(block, size);
                  return block;
                }
              unmap_huge_pages(block, size);
            }
        }
      void *const block = allocate(size);
      if (block == nullptr)
        {
          // realloc() keeps the old block when it fails.
          if (old_size > 0)
            huge_blocks().set(old_block, old_size);
          return nullptr;
        }
      std::memcpy(block,
                  old_block,
                  std::min(size,
                           old_size > 0 ? old_size :
                                          malloc_usable_size(old_block)));
      if (old_size > 0)
        unmap_huge_pages(old_block, old_size);
      else
        std::free(old_block);
      return block;
    }
  } // namespace



  void
  set_up_suitesparse()
  {
    static const bool done = [] {
      const char *const setting = std::getenv("NDDA_HUGE_PAGES");
      if (setting == nullptr || std::string(setting) != "0")
        {
          SuiteSparse_config.malloc_func  = &allocate;
          SuiteSparse_config.calloc_func  = &allocate_zeros;
          SuiteSparse_config.realloc_func = &reallocate;
          SuiteSparse_config.free_func    = &release;
        }
      omp_set_max_active_levels(0);
      return true;
    }();
    (void)done;
  }



  bool
  copy_to_compressed_rows(const dealii::SparseMatrix<double> &matrix,
                          const bool                          upper_only,
                          std::vector<SuiteSparse_long>      &p,
                          std::vector<SuiteSparse_long>      &i,
                          std::vector<double>                &x)
  {
    const SuiteSparse_long        n         = matrix.m();
    const std::size_t             n_entries = upper_only ?
                                                matrix.n_nonzero_elements() / 2 + n :
                                                matrix.n_nonzero_elements();
    std::vector<SuiteSparse_long> new_p(n + 1, 0), new_i;
    new_i.reserve(n_entries);
    x.clear();
    x.reserve(n_entries);
    std::vector<std::pair<SuiteSparse_long, double>> row;
    for (SuiteSparse_long r = 0; r < n; ++r)
      {
        // deal.II keeps the diagonal first in a row: sort by column.
        row.clear();
        for (auto entry = matrix.begin(r); entry != matrix.end(r); ++entry)
          if (!upper_only ||
              static_cast<SuiteSparse_long>(entry->column()) >= r)
            row.emplace_back(entry->column(), entry->value());
        std::sort(row.begin(), row.end(), [](const auto &a, const auto &b) {
          return a.first < b.first;
        });
        for (const auto &[column, value] : row)
          {
            new_i.push_back(column);
            x.push_back(value);
          }
        new_p[r + 1] = new_i.size();
      }
    if (new_p == p && new_i == i)
      return false;
    p.swap(new_p);
    i.swap(new_i);
    return true;
  }
} // namespace ndda
