#ifndef OMPL_PARC_STATESPACES_HUGE_PAGE_MEMORY_
#define OMPL_PARC_STATESPACES_HUGE_PAGE_MEMORY_

#include <cstddef>
#include <new>

namespace ompl_parc
{
    /** \brief Large buffers that fill whole 2 MiB pages (transparent huge pages), allocated once and written all over
        soon after: a team's composite states, the conflict detectors' per-pair arrays.

        Why: the first write to each 4 KiB page of fresh memory is a page fault, tens of microseconds each on a
        virtual machine; at 1024 robots the detectors' per-pair arrays are thousands of such pages before the first
        scan, where huge pages fault in once per 2 MiB. From LARGE bytes on, a
        buffer is mapped on its own, rounded up to whole 2 MiB pages (at most 4x the memory, for a buffer of LARGE
        bytes) and marked for huge pages; smaller ones come from operator new. Where huge pages are off, or the
        mapping could not be aligned, it is ordinary memory; outside Linux every buffer comes from operator new.

        A freed mapping is kept for the next buffer of the same mapped length (the newest first; at most KEPT_MAPPINGS
        of them and KEPT_BYTES in all, the oldest unmapped to make room): a fresh huge page is not only zeroed, on a
        virtual machine its first touch can take milliseconds (the host backing it), and a planner used in a loop (the
        benchmark tool, Python, a user's code) would pay that for its solution path's states at every solve; kept
        mappings are an order of magnitude faster (docs/results.md). */
    class HugePageMemory
    {
      public:
        /** \brief From this size on a buffer gets huge pages. */
        static constexpr std::size_t LARGE = std::size_t{512} << 10;
        /** \brief How many freed mappings, and how many bytes of them in all, are kept for reuse (a larger mapping
            is unmapped when it is freed). */
        static constexpr std::size_t KEPT_MAPPINGS = 8, KEPT_BYTES = std::size_t{64} << 20;

        /** \brief \e bytes of memory aligned for any type of fundamental alignment (throws std::bad_alloc). */
        static void *allocate(std::size_t bytes);

        /** \brief Frees what allocate(\e bytes) returned. */
        static void deallocate(void *memory, std::size_t bytes) noexcept;
    };

    /** \brief A std::vector allocator on HugePageMemory: std::vector<T, HugePageAllocator<T>>. */
    template <typename T>
    struct HugePageAllocator
    {
        using value_type = T;

        HugePageAllocator() = default;
        template <typename U>
        HugePageAllocator(const HugePageAllocator<U> & /*other*/) noexcept
        {
        }

        static_assert(alignof(T) <= alignof(std::max_align_t), "HugePageMemory aligns for fundamental types only");

        T *allocate(std::size_t count)
        {
            if (count > static_cast<std::size_t>(-1) / sizeof(T))
                throw std::bad_alloc();
            return static_cast<T *>(HugePageMemory::allocate(count * sizeof(T)));
        }
        void deallocate(T *memory, std::size_t count) noexcept
        {
            HugePageMemory::deallocate(memory, count * sizeof(T));
        }

        template <typename U>
        bool operator==(const HugePageAllocator<U> & /*other*/) const noexcept
        {
            return true;
        }
        template <typename U>
        bool operator!=(const HugePageAllocator<U> & /*other*/) const noexcept
        {
            return false;
        }
    };
}  // namespace ompl_parc

#endif
