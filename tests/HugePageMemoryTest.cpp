#include "ompl_parc/statespaces/HugePageMemory.h"

#include <gtest/gtest.h>

#include <cerrno>
#include <cstddef>
#include <cstdint>
#include <new>
#include <vector>

#ifdef __linux__
#include <sys/mman.h>
#endif

using namespace ompl_parc;

/* Buffers on both sides of the threshold are aligned for any fundamental type and writable end to end; a large one on
   Linux is mapped on its own at a 2 MiB boundary (so that its pages can be huge), and freeing it unmaps all of that
   (mincore() fails on an unmapped range; ASan checks the small ones). */
TEST(HugePageMemory, SmallAndLargeBuffersAreAlignedAndWritableAndFreed)
{
    for (const std::size_t bytes : {std::size_t{1}, std::size_t{4096}, HugePageMemory::LARGE - 1, HugePageMemory::LARGE,
                                    (std::size_t{5} << 20) + 3})
    {
        auto *memory = static_cast<unsigned char *>(HugePageMemory::allocate(bytes));
        ASSERT_NE(memory, nullptr);
        EXPECT_EQ(reinterpret_cast<std::uintptr_t>(memory) % alignof(std::max_align_t), 0u) << bytes << " bytes";
#if defined(__linux__) && defined(MADV_HUGEPAGE)
        const bool mapped = bytes >= HugePageMemory::LARGE;
        constexpr std::size_t hugePage = std::size_t{2} << 20;
        const std::size_t length = (bytes + hugePage - 1) / hugePage * hugePage;
        if (mapped)
            EXPECT_EQ(reinterpret_cast<std::uintptr_t>(memory) % hugePage, 0u) << bytes << " bytes";
#endif
        memory[bytes - 1] = 7;
        for (std::size_t k = 0; k + 1 < bytes; k += 512)
            memory[k] = static_cast<unsigned char>(k / 512);
        for (std::size_t k = 0; k + 1 < bytes; k += 512)
            ASSERT_EQ(memory[k], static_cast<unsigned char>(k / 512));
        EXPECT_EQ(memory[bytes - 1], 7);
        HugePageMemory::deallocate(memory, bytes);
#if defined(__linux__) && defined(MADV_HUGEPAGE)
        if (mapped)
        {
            std::vector<unsigned char> resident(length / 4096);
            errno = 0;
            EXPECT_EQ(mincore(memory, length, resident.data()), -1) << bytes << " bytes: still mapped";
            EXPECT_EQ(errno, ENOMEM);
        }
#endif
    }
    HugePageMemory::deallocate(nullptr, HugePageMemory::LARGE);  // like operator delete: nothing to free
}

/* A vector on the allocator keeps its contents while it grows past the threshold and shrinks back below it. */
TEST(HugePageMemory, VectorsGrowAndShrinkAcrossTheThreshold)
{
    std::vector<std::size_t, HugePageAllocator<std::size_t>> values;
    const std::size_t large = 2 * HugePageMemory::LARGE / sizeof(std::size_t);
    for (std::size_t k = 0; k < large; ++k)
        values.push_back(k * 3);
    for (std::size_t k = 0; k < large; k += 997)
        ASSERT_EQ(values[k], k * 3);
    values.resize(10);
    values.shrink_to_fit();
    EXPECT_EQ(values[9], 27u);
    EXPECT_THROW(HugePageAllocator<std::size_t>().allocate(static_cast<std::size_t>(-1) / 4), std::bad_alloc);
}
