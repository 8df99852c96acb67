// The CAN cycle allocates nothing once the drives run: every operator new in this executable is
// counted while the counter is on. Counted: the adapter's read()/write() (master, CiA 402 axes,
// supervision, the stop reaction), the virtual bus, the simulated drives and the trace writer.
#include <atomic>
#include <cstdlib>
#include <new>

#include <gtest/gtest.h>

#include "tests/drivers/system/drive_rig.h"
#include "tests/drivers/system/test_machines.h"

namespace {

std::atomic<bool> g_counting{false};
std::atomic<size_t> g_allocations{0};

void* allocate(size_t size, size_t alignment = 0) {
    if (g_counting.load(std::memory_order_relaxed))
        g_allocations.fetch_add(1, std::memory_order_relaxed);
    size = size == 0 ? 1 : size;
    void* p = alignment > alignof(std::max_align_t)
                  ? std::aligned_alloc(alignment, (size + alignment - 1) / alignment * alignment)
                  : std::malloc(size);
    if (!p) throw std::bad_alloc();
    return p;
}

struct Counting {
    Counting() {
        g_allocations = 0;
        g_counting = true;
    }
    ~Counting() { g_counting = false; }
    size_t count() const { return g_allocations.load(); }
};

}  // namespace

void* operator new(size_t size) {
    return allocate(size);
}
void* operator new[](size_t size) {
    return allocate(size);
}
void* operator new(size_t size, std::align_val_t a) {
    return allocate(size, static_cast<size_t>(a));
}
void* operator new[](size_t size, std::align_val_t a) {
    return allocate(size, static_cast<size_t>(a));
}
void* operator new(size_t size, const std::nothrow_t&) noexcept {
    try {
        return allocate(size);
    } catch (...) {
        return nullptr;
    }
}
void* operator new[](size_t size, const std::nothrow_t& t) noexcept {
    return operator new(size, t);
}
void operator delete(void* p) noexcept {
    std::free(p);
}
void operator delete[](void* p) noexcept {
    std::free(p);
}
void operator delete(void* p, size_t) noexcept {
    std::free(p);
}
void operator delete[](void* p, size_t) noexcept {
    std::free(p);
}
void operator delete(void* p, std::align_val_t) noexcept {
    std::free(p);
}
void operator delete[](void* p, std::align_val_t) noexcept {
    std::free(p);
}
void operator delete(void* p, size_t, std::align_val_t) noexcept {
    std::free(p);
}
void operator delete[](void* p, size_t, std::align_val_t) noexcept {
    std::free(p);
}

namespace kerf::drivers {
namespace {

TEST(CanCycleAllocations, TheCounterSeesAllocations) {
    Counting counting;
    auto* p = new int(1);
    delete p;
    EXPECT_EQ(counting.count(), 1u);
}

TEST(CanCycleAllocations, NoneWhileTheDrivesFollowTheirSetpoints) {
    CanSimOptions options;
    options.tracePath = test::tempFile("alloc_trace.log");
    test::DriveRig rig(test::mill(), options);
    ASSERT_TRUE(rig.boot());
    rig.run(0.3);  // heartbeats, trace buffer, every path once
    Counting counting;
    for (int k = 0; k < 2000; ++k) {
        rig.setpoint(0) += 0.01;  // X at 10 mm/s
        rig.setpoint(3) += 12.0;  // spindle at 2000 rpm
        rig.cycle();
    }
    EXPECT_EQ(counting.count(), 0u);
}

TEST(CanCycleAllocations, NoneWhenAFaultStopsEverything) {
    CanSimOptions options;
    options.faults.push_back(parseFaultInjection("2:heartbeat@0.2").value());
    options.faults.push_back(parseFaultInjection("3:pdo@0.6").value());
    test::DriveRig rig(test::mill(), options);
    ASSERT_TRUE(rig.boot());
    Counting counting;
    rig.run(0.8);
    rig.run(0.2, false);  // motion in fault: no write()
    EXPECT_TRUE(rig.adapter().stopped());
    EXPECT_EQ(counting.count(), 0u);
}

}  // namespace
}  // namespace kerf::drivers
