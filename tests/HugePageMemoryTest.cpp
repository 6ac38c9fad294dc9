#include "ompl_parc/statespaces/HugePageMemory.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <new>
#include <vector>

using namespace ompl_parc;

/* Buffers on both sides of the threshold are aligned for any type and writable end to end; a large one on Linux is
   mapped on its own at a 2 MiB boundary (so that its pages can be huge). Freeing each one is checked by ASan. */
TEST(HugePageMemory, SmallAndLargeBuffersAreAlignedAndWritableAndFreed)
{
    for (const std::size_t bytes : {std::size_t{1}, std::size_t{4096}, HugePageMemory::LARGE - 1, HugePageMemory::LARGE,
                                    (std::size_t{5} << 20) + 3})
    {
        auto *memory = static_cast<unsigned char *>(HugePageMemory::allocate(bytes));
        ASSERT_NE(memory, nullptr);
        EXPECT_EQ(reinterpret_cast<std::uintptr_t>(memory) % alignof(std::max_align_t), 0u) << bytes << " bytes";
#ifdef __linux__
        if (bytes >= HugePageMemory::LARGE)
            EXPECT_EQ(reinterpret_cast<std::uintptr_t>(memory) % (std::size_t{2} << 20), 0u) << bytes << " bytes";
#endif
        memory[bytes - 1] = 7;
        for (std::size_t k = 0; k + 1 < bytes; k += 512)
            memory[k] = static_cast<unsigned char>(k / 512);
        for (std::size_t k = 0; k + 1 < bytes; k += 512)
            ASSERT_EQ(memory[k], static_cast<unsigned char>(k / 512));
        EXPECT_EQ(memory[bytes - 1], 7);
        HugePageMemory::deallocate(memory, bytes);
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
