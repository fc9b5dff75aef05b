// The dealing model (app/mpi/model/DealModel.h) on cases worked out by hand: the pool's
// schedule, rank 0 alone, a remote rank's round trips through the links and the dealer, rank 0's
// link as the bottleneck, and a frame written by whoever brought its last pixels. The numbers
// are chosen to be exact in binary (powers of two), so the expected times are exact.
#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "DealModel.h"

namespace rt::mpi::model {
namespace {

/// No latency, no dealer time, links so fast that nothing waits on them.
Network instant() { return Network{1e300, 0}; }
Dealer free() { return Dealer{0, 0, 0}; }

TEST(DealtTileSide, ThirtyTwoUntilThereAreFewerThanEightTilesAThread) {
  // 1280 x 720: 40 x 23 = 920 tiles of 32, 80 x 45 = 3600 of 16, 160 x 90 = 14400 of 8.
  EXPECT_EQ(dealtTileSide(1280, 720, 1, 2), 32);
  EXPECT_EQ(dealtTileSide(1280, 720, 1, 115), 32);  // 920 = 8 x 115
  EXPECT_EQ(dealtTileSide(1280, 720, 1, 116), 16);
  EXPECT_EQ(dealtTileSide(1280, 720, 1, 450), 16);  // 3600 = 8 x 450
  EXPECT_EQ(dealtTileSide(1280, 720, 1, 451), 8);
  EXPECT_EQ(dealtTileSide(1280, 720, 1, 100000), 8);  // never below 8
  EXPECT_EQ(dealtTileSide(1280, 720, 2, 230), 32);    // two frames' tiles: 1840
  EXPECT_EQ(dealtTileSide(48, 27, 1, 3), 8);          // 2 tiles of 32, 6 of 16, 24 of 8
  EXPECT_EQ(dealtTileSide(1, 1, 1, 0), 8);
}

TEST(PoolSeconds, EachTileGoesToTheFirstFreeThread) {
  // Two threads: 4 | 1, 1, 1 -> the second takes 1, 1, 1 while the first runs 4; then 2 waits.
  EXPECT_EQ(poolSeconds({4, 1, 1, 1, 2}, 2), 5);
  EXPECT_EQ(poolSeconds({4, 1, 1, 1, 2}, 1), 9);
  EXPECT_EQ(poolSeconds({}, 3), 0);
  EXPECT_THROW(poolSeconds({1}, 0), std::invalid_argument);
}

TEST(Replay, RankZeroAloneIsThePoolPlusTheFramesWrite) {
  const std::vector<Unit> units{{4, 100, 0}, {1, 100, 0}, {1, 100, 0}, {1, 100, 0}, {2, 100, 0}};
  const Outcome r = replay(units, {1, 2}, instant(), Dealer{0, 0, 0.5}, 40);
  EXPECT_EQ(r.seconds, 5.5);  // the pool's 5, then the thread with the last tile writes
  EXPECT_EQ(r.computeSeconds, 9);
  EXPECT_EQ(r.messages, 0u);  // rank 0's own threads send nothing
  EXPECT_EQ(r.bytes, 0u);
}

TEST(Replay, ARemoteRankPaysTheLatencyBothWaysAndTheDealer) {
  // One thread on rank 0, one on rank 1; every unit costs 1; latency 1/8, the dealer 1/16 a
  // message. Rank 0 takes unit 0 at 0 and unit 2 at 1. Rank 1's empty request arrives at 1/8
  // and is answered at 3/16 with unit 1, which arrives at 5/16 and is done at 21/16; its result
  // arrives at 23/16, answered at 3/2 with unit 3, done at 21/8, arriving at 22/8, answered
  // ("no more") at 45/16. Rank 0's thread finds nothing left at 2.
  const std::vector<Unit> units(4, Unit{1, 0, 0});
  const Outcome r = replay(units, {2, 1}, Network{1e300, 0.125}, Dealer{0.0625, 0, 0}, 0);
  EXPECT_EQ(r.seconds, 2.8125);
  EXPECT_EQ(r.messages, 6u);  // three requests (the first empty, two with results), three answers
  EXPECT_EQ(r.lastUnitStart, 1.5);
  EXPECT_EQ(r.dealerBusy, 3 * 0.0625);
}

TEST(Replay, RankZerosLinkCarriesOneMessageAtATime) {
  // Rank 0's thread is busy with unit 0 until 2.5; three remote machines, units 1 to 3 costing
  // nothing, results of 8 bytes over links of 8 bytes/s (1 s each), no latency. Unit 1 goes to
  // rank 1 at 0; its result occupies rank 0's link from 0 to 1, so the other empty requests
  // arrive at 1: rank 1 gets unit 2 and rank 2 unit 3 at 1. Both results leave their machines
  // at 2, and rank 0's link takes them one after the other: at 2 and at 3.
  const std::vector<Unit> units{{2.5, 8, 0}, {0, 8, 1}, {0, 8, 2}, {0, 8, 3}};
  const Outcome r = replay(units, {4, 1}, Network{8, 0}, free(), 0);
  EXPECT_EQ(r.seconds, 3);
  EXPECT_EQ(r.linkBusy, 3);
  EXPECT_EQ(r.bytes, 3 * 8 + 6 * 8u);  // three results; six answers of 8 bytes
  // Without the queue (links a thousand times faster) rank 0's own unit is the end.
  EXPECT_EQ(replay(units, {4, 1}, Network{8000, 0}, free(), 0).seconds, 2.5);
}

TEST(Replay, AnIdleDealerAnswersHalfAPollLater) {
  // Rank 0's thread takes the only unit at 0; rank 1's empty request reaches an idle dealer at
  // 0 and is answered "no more" half a poll (of 1 s) later.
  const std::vector<Unit> units{{0, 0, 0}};
  const Outcome r = replay(units, {2, 1}, instant(), Dealer{0, 1, 0}, 0);
  EXPECT_EQ(r.seconds, 0.5);
}

TEST(Replay, TheDealerWritesAFrameARemoteRankCompleted) {
  // Two frames of one unit each: rank 0's thread takes frame 0 (cost 4), rank 1 frame 1
  // (cost 1), whose result reaches the dealer at 1: it writes the frame (2 s), busy until 3;
  // rank 0's thread writes frame 0 itself, from 4 to 6.
  const std::vector<Unit> units{{4, 0, 0}, {1, 0, 1}};
  const Outcome r = replay(units, {2, 1}, instant(), Dealer{0, 0, 2}, 0);
  EXPECT_EQ(r.seconds, 6);
  EXPECT_EQ(r.dealerBusy, 2);
}

TEST(Replay, RefusesAClusterWithoutWorkers) {
  EXPECT_THROW(replay({}, {0, 8}, instant(), free(), 0), std::invalid_argument);
  EXPECT_THROW(replay({}, {4, 0}, instant(), free(), 0), std::invalid_argument);
}

}  // namespace
}  // namespace rt::mpi::model
