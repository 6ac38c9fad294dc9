#include "ompl_parc/statespaces/HugePageMemory.h"

#include <cstdint>
#include <limits>

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
        munmap(memory, mappedLength(bytes));
        return;
    }
#endif
    ::operator delete(memory);
}
