#include "ompl_parc/statespaces/HugePageMemory.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <limits>
#include <mutex>
#include <vector>

#ifdef __linux__
#include <sys/mman.h>
#endif

#if defined(__linux__) && defined(MADV_HUGEPAGE)
namespace
{
    constexpr std::size_t HUGE_PAGE = std::size_t{2} << 20;

    /** The mapping of a large buffer of \e bytes: whole huge pages. */
    std::size_t mappedLength(std::size_t bytes)
    {
        return (bytes + HUGE_PAGE - 1) / HUGE_PAGE * HUGE_PAGE;
    }

    /** True if a buffer of \e bytes is mapped on its own (allocate() and deallocate() must agree). */
    bool mappedOnItsOwn(std::size_t bytes)
    {
        return bytes >= ompl_parc::HugePageMemory::LARGE && bytes <= std::numeric_limits<std::size_t>::max() / 2;
    }

    using ompl_parc::HugePageMemory;

    /** Mappings freed lately, kept for the next allocate() of the same mapped length (see HugePageMemory): at most
        HugePageMemory::KEPT_MAPPINGS of them and HugePageMemory::KEPT_BYTES in all, the oldest unmapped first. */
    class KeptMappings
    {
      public:
        KeptMappings() { kept_.reserve(HugePageMemory::KEPT_MAPPINGS); }

        /** The newest kept mapping of \e length bytes, or null. */
        void *take(std::size_t length)
        {
            const std::lock_guard<std::mutex> lock(mutex_);
            const auto newest = std::find_if(kept_.rbegin(), kept_.rend(),
                                             [length](const Mapping &mapping) { return mapping.length == length; });
            if (newest == kept_.rend())
                return nullptr;
            void *memory = newest->memory;
            bytes_ -= length;
            kept_.erase(std::next(newest).base());
            return memory;
        }

        /** Keep \e memory (\e length bytes mapped), unmapping the oldest kept ones to make room; a mapping larger
            than KEPT_BYTES is unmapped at once. */
        void keep(void *memory, std::size_t length)
        {
            if (length > HugePageMemory::KEPT_BYTES)
            {
                munmap(memory, length);
                return;
            }
            const std::lock_guard<std::mutex> lock(mutex_);
            while (kept_.size() == HugePageMemory::KEPT_MAPPINGS || bytes_ + length > HugePageMemory::KEPT_BYTES)
            {
                munmap(kept_.front().memory, kept_.front().length);
                bytes_ -= kept_.front().length;
                kept_.erase(kept_.begin());
            }
            kept_.push_back({memory, length});  // within the capacity reserved: never allocates
            bytes_ += length;
        }

      private:
        struct Mapping
        {
            void *memory;
            std::size_t length;
        };
        std::mutex mutex_;
        std::vector<Mapping> kept_;  // oldest first
        std::size_t bytes_{0};
    };

    /** The process's kept mappings; never destroyed (a buffer may be freed while statics are destroyed). */
    KeptMappings &keptMappings()
    {
        static auto *kept = new KeptMappings;
        return *kept;
    }
}  // namespace
#endif

void *ompl_parc::HugePageMemory::allocate(std::size_t bytes)
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    if (mappedOnItsOwn(bytes))
    {
        // Map one huge page more than needed and keep the 2 MiB-aligned part: only aligned 2 MiB ranges can be huge
        // pages.
        const std::size_t length = mappedLength(bytes);
        if (void *kept = keptMappings().take(length))
            return kept;
        void *raw = mmap(nullptr, length + HUGE_PAGE, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
        if (raw == MAP_FAILED)  // no room for the extra page: unaligned, on ordinary pages (freed the same way)
        {
            raw = mmap(nullptr, length, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
            if (raw == MAP_FAILED)
                throw std::bad_alloc();
            return raw;
        }
        const auto start = reinterpret_cast<std::uintptr_t>(raw);
        const std::uintptr_t aligned = (start + HUGE_PAGE - 1) & ~std::uintptr_t{HUGE_PAGE - 1};
        if (aligned > start)
            munmap(raw, aligned - start);
        if (const std::size_t tail = start + HUGE_PAGE - aligned; tail > 0)
            munmap(reinterpret_cast<void *>(aligned + length), tail);
        // Only a hint: where transparent huge pages are off this is ordinary memory.
        madvise(reinterpret_cast<void *>(aligned), length, MADV_HUGEPAGE);
        return reinterpret_cast<void *>(aligned);
    }
#endif
    return ::operator new(bytes);
}

void ompl_parc::HugePageMemory::deallocate(void *memory, std::size_t bytes) noexcept
{
    if (memory == nullptr)
        return;
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    if (mappedOnItsOwn(bytes))
    {
        keptMappings().keep(memory, mappedLength(bytes));
        return;
    }
#endif
    ::operator delete(memory);
}
