#include "ompl_parc/statespaces/HugePageMemory.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cerrno>
#include <cstddef>
#include <cstdint>
#include <new>
#include <thread>
#include <vector>

#ifdef __linux__
#include <sys/mman.h>
#endif

using namespace ompl_parc;

namespace
{
    constexpr std::size_t HUGE_PAGE = std::size_t{2} << 20;

#if defined(__linux__) && defined(MADV_HUGEPAGE)
    /** True if \e length bytes from \e memory are mapped (mincore() fails with ENOMEM on an unmapped range). */
    bool isMapped(void *memory, std::size_t length)
    {
        std::vector<unsigned char> resident(length / 4096);
        errno = 0;
        if (mincore(memory, length, resident.data()) == 0)
            return true;
        EXPECT_EQ(errno, ENOMEM);
        return false;
    }
#endif
}  // namespace

/* Buffers on both sides of the threshold are aligned for any fundamental type and writable end to end; a large one on
   Linux is mapped on its own at a 2 MiB boundary (so that its pages can be huge). ASan checks the small ones. */
TEST(HugePageMemory, SmallAndLargeBuffersAreAlignedAndWritable)
{
    for (const std::size_t bytes : {std::size_t{1}, std::size_t{4096}, HugePageMemory::LARGE - 1, HugePageMemory::LARGE,
                                    (std::size_t{5} << 20) + 3})
    {
        auto *memory = static_cast<unsigned char *>(HugePageMemory::allocate(bytes));
        ASSERT_NE(memory, nullptr);
        EXPECT_EQ(reinterpret_cast<std::uintptr_t>(memory) % alignof(std::max_align_t), 0u) << bytes << " bytes";
#if defined(__linux__) && defined(MADV_HUGEPAGE)
        if (bytes >= HugePageMemory::LARGE)
            EXPECT_EQ(reinterpret_cast<std::uintptr_t>(memory) % HUGE_PAGE, 0u) << bytes << " bytes";
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

#if defined(__linux__) && defined(MADV_HUGEPAGE)
/* A freed large buffer is kept for the next one of the same mapped length (the newest first), up to KEPT_MAPPINGS
   mappings, the oldest unmapped to make room; one larger than KEPT_BYTES is unmapped when it is freed. */
TEST(HugePageMemory, FreedMappingsAreKeptForTheNextBufferOfTheirLengthWithinBounds)
{
    const std::size_t bytes = HUGE_PAGE + 3;  // mapped as two huge pages
    void *first = HugePageMemory::allocate(bytes);
    HugePageMemory::deallocate(first, bytes);
    EXPECT_TRUE(isMapped(first, 2 * HUGE_PAGE));
    void *again = HugePageMemory::allocate(2 * HUGE_PAGE - 5);  // the same mapped length
    EXPECT_EQ(again, first);
    static_cast<unsigned char *>(again)[2 * HUGE_PAGE - 6] = 1;
    HugePageMemory::deallocate(again, 2 * HUGE_PAGE - 5);

    // One more freed than can be kept: the oldest goes, the others stay.
    std::vector<void *> buffers;
    for (std::size_t k = 0; k <= HugePageMemory::KEPT_MAPPINGS; ++k)
        buffers.push_back(HugePageMemory::allocate(HugePageMemory::LARGE));
    for (void *buffer : buffers)
        HugePageMemory::deallocate(buffer, HugePageMemory::LARGE);
    EXPECT_FALSE(isMapped(buffers.front(), HUGE_PAGE));
    for (std::size_t k = 1; k < buffers.size(); ++k)
        EXPECT_TRUE(isMapped(buffers[k], HUGE_PAGE)) << k;

    const std::size_t huge = HugePageMemory::KEPT_BYTES + 1;
    void *large = HugePageMemory::allocate(huge);
    HugePageMemory::deallocate(large, huge);
    EXPECT_FALSE(isMapped(large, HugePageMemory::KEPT_BYTES + HUGE_PAGE));
}
#endif

/* Threads allocating and freeing large buffers of a few lengths at once (run under TSan) each find their own contents:
   a kept mapping is handed to one buffer at a time. */
TEST(HugePageMemory, ThreadsSharingKeptMappingsKeepTheirContents)
{
    std::vector<std::thread> threads;
    std::atomic<unsigned int> mismatches{0};
    for (unsigned int t = 0; t < 4; ++t)
        threads.emplace_back(
            [t, &mismatches]
            {
                for (unsigned int round = 0; round < 50; ++round)
                {
                    const std::size_t bytes = HugePageMemory::LARGE * (1 + (t + round) % 3);
                    auto *memory = static_cast<unsigned int *>(HugePageMemory::allocate(bytes));
                    const std::size_t count = bytes / sizeof(unsigned int);
                    for (std::size_t k = 0; k < count; k += 1024)
                        memory[k] = t * 1000 + round;
                    std::this_thread::yield();
                    for (std::size_t k = 0; k < count; k += 1024)
                        if (memory[k] != t * 1000 + round)
                            ++mismatches;
                    HugePageMemory::deallocate(memory, bytes);
                }
            });
    for (auto &thread : threads)
        thread.join();
    EXPECT_EQ(mismatches.load(), 0u);
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
