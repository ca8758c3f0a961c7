// Holding threads on cores: a hold restricts a thread to the cores given and its release gives
// back the ones it had, for the calling thread and another; moved holds release once; and the
// meshlet stream's consumer hold takes one core. Where the process may use only one core nothing
// is held, which the tests check too.
#include <gtest/gtest.h>

#include <atomic>
#include <thread>

#include "TestMeshes.h"
#include "core/meshopt/CoreAffinity.h"
#include "core/meshopt/Meshopt.h"

namespace conescope {
namespace {

bool severalCores() { return coresOf(thisThread()).count() >= 2; }

TEST(CoreAffinity, SplitCoresIsTheCurrentCoreAndTheOthers) {
    const Cores before = coresOf(thisThread());
    const CoreSplit split = splitCores();
    if (before.count() < 2) {
        EXPECT_TRUE(split.current.none() && split.others.none());
        return;
    }
    EXPECT_EQ(split.current.count(), 1u);
    EXPECT_TRUE((split.current & split.others).none());
    EXPECT_EQ(split.current | split.others, before);
}

TEST(CoreAffinity, HoldOnTheCallingThreadIsReleasedToTheCoresItHad) {
    const Cores before = coresOf(thisThread());
    const CoreSplit split = splitCores();
    {
        CoreHold hold(thisThread(), split.current);
        EXPECT_EQ(hold.held(), split.current.any());
        if (hold.held()) EXPECT_EQ(coresOf(thisThread()), split.current);
        hold.release();
        EXPECT_FALSE(hold.held());
        EXPECT_EQ(coresOf(thisThread()), before);
        hold.release();  // twice changes nothing
        EXPECT_EQ(coresOf(thisThread()), before);
    }
    {
        CoreHold hold(thisThread(), split.current);
    }  // the destructor releases
    EXPECT_EQ(coresOf(thisThread()), before);
}

TEST(CoreAffinity, HoldOnAnotherThreadAndMovedHoldsReleaseOnce) {
    if (!severalCores()) GTEST_SKIP() << "one core: nothing is held";
    std::atomic<bool> stop{false};
    std::thread other([&] {
        while (!stop) std::this_thread::yield();
    });
    const Cores before = coresOf(other.native_handle());
    const CoreSplit split = splitCores();
    CoreHold hold(other.native_handle(), split.others);
    EXPECT_TRUE(hold.held());
    EXPECT_EQ(coresOf(other.native_handle()), split.others);
    CoreHold moved(std::move(hold));
    EXPECT_FALSE(hold.held());
    EXPECT_TRUE(moved.held());
    hold.release();  // the moved-from hold holds nothing
    EXPECT_EQ(coresOf(other.native_handle()), split.others);
    CoreHold assigned;
    assigned = std::move(moved);
    assigned.release();
    EXPECT_EQ(coresOf(other.native_handle()), before);
    stop = true;
    other.join();
}

TEST(CoreAffinity, EmptyCoresHoldNothing) {
    const Cores before = coresOf(thisThread());
    CoreHold hold(thisThread(), Cores());
    EXPECT_FALSE(hold.held());
    EXPECT_EQ(coresOf(thisThread()), before);
}

TEST(CoreAffinity, MeshletStreamConsumerHoldsOneCoreUntilReleased) {
    const Cores before = coresOf(thisThread());
    const bool several = severalCores();
    MeshletStream stream(std::make_shared<const Mesh>(testmesh::torus(1.0, 0.35, 64, 32)), MeshletLimits{64, 124}, 4);
    {
        CoreHold hold = stream.holdConsumerCore();
        EXPECT_EQ(hold.held(), several);
        if (hold.held()) EXPECT_EQ(coresOf(thisThread()).count(), 1u);
    }
    EXPECT_EQ(coresOf(thisThread()), before);
    EXPECT_GT(stream.meshletCount(), 0u);
    EXPECT_TRUE(stream.allPartsMade());
}

}  // namespace
}  // namespace conescope
