// `mpirun -np N amrstream trace ... --distribute seeds` against one process (no mpirun): the same
// lines in the same order, steps and reasons exactly, every point array bit for bit on the CPU
// and on each GPU backend (lavapipe, validation layers on: each line's arithmetic does not depend
// on which lines share its batch); a rank that fails ends every rank with its error and no output.

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sched.h>

#include <algorithm>
#include <cctype>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <thread>

#include "mpi/gathered_traces.hpp"
#include "output/vtp_reader.hpp"
#include "run_amrstream.hpp"
#include "temp_dir_test.hpp"

namespace amrstream {
namespace {

using ::testing::HasSubstr;

// The launcher of `ranks` ranks. Ranks bound to one core each (mpirun's default) would leave
// lavapipe and the CPU tracer one thread; the tests' processes may share the cores. With
// `validated`, every rank runs with the Vulkan validation layers (-x passes the variable on),
// and a validation error fails its run.
std::string launcher(int ranks, bool validated = false) {
  return std::string("OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 ") +
         (validated ? "AMRSTREAM_VALIDATION=1 " : "") + AMRSTREAM_MPIEXEC +
         (validated ? " -x AMRSTREAM_VALIDATION" : "") + " --oversubscribe --bind-to none -np " +
         std::to_string(ranks);
}

testing::Outcome mpirun(int ranks, const std::string& arguments, bool validated = false) {
  return testing::runAmrstream(arguments, launcher(ranks, validated));
}

void expectSameTraces(const flow::TraceSet& one, const flow::TraceSet& many) {
  ASSERT_EQ(one.lineCount(), many.lineCount());
  EXPECT_EQ(one.seedIds, many.seedIds);
  EXPECT_EQ(one.directions, many.directions);
  EXPECT_EQ(one.steps, many.steps);
  EXPECT_EQ(one.reasons, many.reasons);
  EXPECT_EQ(one.offsets, many.offsets);
  EXPECT_EQ(one.channelNames, many.channelNames);
  ASSERT_EQ(one.pointCount(), many.pointCount());
  const auto same = [](const auto& a, const auto& b) {
    return a.size() == b.size() &&
           std::memcmp(a.data(), b.data(), a.size() * sizeof(*a.data())) == 0;
  };
  EXPECT_TRUE(same(one.positions, many.positions));
  EXPECT_TRUE(same(one.times, many.times));
  EXPECT_TRUE(same(one.vectors, many.vectors));
  EXPECT_TRUE(same(one.channels, many.channels));
  EXPECT_TRUE(same(one.vorticity, many.vorticity));
}

// The hand-offs a run over data printed ("hand-offs 12 / 0 / 7 (...)"), summed over the ranks;
// -1 when it printed none.
long handOffs(const std::string& output) {
  std::size_t at = output.find("hand-offs ");
  if (at == std::string::npos) return -1;
  long sum = 0;
  for (at += 10; at < output.size() && std::isdigit(static_cast<unsigned char>(output[at]));) {
    std::size_t used = 0;
    sum += std::stol(output.substr(at), &used);
    at += used;
    if (output.compare(at, 3, " / ") != 0) break;
    at += 3;
  }
  return sum;
}

class MpiTraceTest : public testing::TempDirTest {
 protected:
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  // The traces of `arguments` in one process and on each rank count, compared.
  // `oneProcess`: the command without mpirun, when it differs. Returns the last run's output.
  std::string expectRanksAgree(const std::string& arguments, std::initializer_list<int> rankCounts,
                               const std::string& oneProcess = "") {
    const testing::Outcome single = testing::runAmrstream(
        (oneProcess.empty() ? arguments : oneProcess) + " --out " + path("one.vtp"));
    EXPECT_EQ(single.status, 0) << single.output;
    if (single.status != 0) return {};
    const flow::TraceSet one = output::readVtpTraces(path("one.vtp"));
    std::string last;
    for (const int ranks : rankCounts) {
      SCOPED_TRACE(std::to_string(ranks) + " ranks");
      const std::string out = path("ranks" + std::to_string(ranks) + ".vtp");
      const testing::Outcome run = mpirun(ranks, arguments + " --out " + out);
      EXPECT_EQ(run.status, 0) << run.output;
      if (run.status != 0) continue;
      last = run.output;
      if (ranks > 1) {
        EXPECT_THAT(run.output, HasSubstr("ranks      " + std::to_string(ranks) + " "));
      }
      // Rank 0 alone prints: one summary.
      EXPECT_EQ(run.output.find("input      "), run.output.rfind("input      "));
      expectSameTraces(one, output::readVtpTraces(out));
    }
    return last;
  }
};

TEST_F(MpiTraceTest, BothDirectionsWithPointDataOnTheCpu) {
  expectRanksAgree("trace builtin:cloud --backend cpu --count 150 --steps 600", {1, 2, 3});
}

TEST_F(MpiTraceTest, ForwardOnAPeriodicFieldFromASeedGrid) {
  expectRanksAgree(
      "trace builtin:abc --backend cpu --seed-grid 4,3,2 --steps 800 "
      "--direction forward --vorticity",
      {2, 3});
}

// The lines handed on between ranks that a run printed ("lines handed on 3 / 0 / 5"), summed;
// -1 when it printed none.
long linesHandedOn(const std::string& output) {
  const std::size_t at = output.find("lines handed on ");
  return at == std::string::npos ? -1 : handOffs("hand-offs " + output.substr(at + 16));
}

// --rebalance-steps: rounds of 70 steps, the live lines evened out among the ranks between them,
// against one process without rounds; lines do go from rank to rank.
TEST_F(MpiTraceTest, RebalancedRoundsOnTheCpu) {
  const std::string one = "trace builtin:cloud --backend cpu --count 150 --steps 600";
  const std::string last = expectRanksAgree(one + " --rebalance-steps 70", {1, 2, 3}, one);
  EXPECT_THAT(last, HasSubstr("evened out every 70 steps"));
  EXPECT_GT(linesHandedOn(last), 0) << last;
}

TEST_F(MpiTraceTest, RebalanceStepsAreForSeeds) {
  const testing::Outcome run = testing::runAmrstream(
      "trace builtin:rotation --count 4 --distribute data --rebalance-steps 10 --out " +
      path("x.vtp"));
  EXPECT_EQ(run.status, 2) << run.output;
  EXPECT_THAT(run.output, HasSubstr("--rebalance-steps"));
  EXPECT_FALSE(std::filesystem::exists(path("x.vtp")));
}

// Enough seeds for several blocks of the Morton order on each rank.
TEST_F(MpiTraceTest, ManyBlocksOfSeedsDealtRoundTheRanks) {
  expectRanksAgree(
      "trace builtin:rotation --backend cpu --count 13000 --steps 40 "
      "--point-data none",
      {2, 3});
}

// The pieces' lines read as one process's (mpi::GatheredTraces orders them by direction and
// seed id), their points copied out.
flow::TraceSet mergedPieces(std::vector<flow::TraceSet> pieces) {
  const mpi::GatheredTraces gathered(std::move(pieces));
  flow::TraceSet merged = gathered.lines();
  std::vector<float> scratch;
  for (std::size_t line = 0; line < merged.lineCount(); ++line) {
    const std::span<const float> p = gathered.column(flow::PointColumn::Positions, line, scratch);
    for (std::size_t k = 0; k < p.size(); k += 3)
      merged.positions.push_back({p[k], p[k + 1], p[k + 2]});
    for (const float t : gathered.column(flow::PointColumn::Times, line, scratch))
      merged.times.push_back(t);
    const std::span<const float> v = gathered.column(flow::PointColumn::Vectors, line, scratch);
    for (std::size_t k = 0; k < v.size(); k += 3)
      merged.vectors.push_back({v[k], v[k + 1], v[k + 2]});
    for (const float c : gathered.column(flow::PointColumn::Channels, line, scratch))
      merged.channels.push_back(c);
  }
  return merged;
}

// Forward lines, then backward ones, from line `first` of `total` on (a line of one point has no
// IntegrationTime to tell its direction by).
void setDirectionsByHalves(flow::TraceSet& t, std::size_t first, std::size_t total) {
  for (std::size_t line = 0; line < t.lineCount(); ++line)
    t.directions[line] = first + line < total / 2 ? 1.0f : -1.0f;
}

// --pieces: each rank writes its own lines beside the .pvtp; the pieces hold one process's lines
// between them, and VTK's parallel reader opens the .pvtp.
class MpiPiecesTest : public MpiTraceTest {
 protected:
  // Over seeds, a piece holds the lines of its rank's seeds, forward then backward; over data,
  // the pieces in rank order hold the lines in one process's order.
  void expectPiecesHoldOneProcess(const std::string& arguments, bool overData) {
    ASSERT_EQ(testing::runAmrstream(arguments + " --out " + path("one.vtp")).status, 0);
    flow::TraceSet one = output::readVtpTraces(path("one.vtp"));
    const std::size_t total = one.lineCount();
    setDirectionsByHalves(one, 0, total);
    const testing::Outcome run = mpirun(3, arguments + (overData ? " --distribute data" : "") +
                                               " --pieces --out " + path("lines.pvtp"));
    ASSERT_EQ(run.status, 0) << run.output;
    EXPECT_THAT(run.output,
                HasSubstr("(3 pieces lines_0.vtp.., " + std::to_string(total) + " polylines"));
    std::vector<flow::TraceSet> pieces;
    std::size_t first = 0;
    for (int rank = 0; rank < 3; ++rank) {
      pieces.push_back(output::readVtpTraces(path("lines_" + std::to_string(rank) + ".vtp")));
      EXPECT_GT(pieces.back().lineCount(), 0u);
      if (overData)
        setDirectionsByHalves(pieces.back(), first, total);
      else
        setDirectionsByHalves(pieces.back(), 0, pieces.back().lineCount());
      first += pieces.back().lineCount();
    }
    expectSameTraces(one, mergedPieces(std::move(pieces)));

    const auto readByVtk = [&](const std::string& file) {
      return testing::runAmrstream("", std::string(AMRSTREAM_VTK_PYTHON) + " " +
                                           AMRSTREAM_READ_PVTP + " " + path(file) + " #");
    };
    const testing::Outcome parallel = readByVtk("lines.pvtp"), single = readByVtk("one.vtp");
    ASSERT_EQ(parallel.status, 0) << parallel.output;
    EXPECT_THAT(parallel.output, HasSubstr(std::to_string(total) + " "));
    EXPECT_THAT(parallel.output, HasSubstr(" mag,dens,IntegrationTime,Speed\n"));
    EXPECT_EQ(parallel.output, single.output);
    lastRun_ = run.output;
  }
  std::string lastRun_;
};

TEST_F(MpiPiecesTest, OverSeeds) {
  expectPiecesHoldOneProcess("trace builtin:cloud --backend cpu --count 120 --steps 400", false);
}

// Over data the ranks first send each line's runs to the rank whose piece holds the line.
TEST_F(MpiPiecesTest, OverDataWithLinesCrossingParts) {
  expectPiecesHoldOneProcess(
      "trace builtin:cloud --backend cpu --count 120 --steps 400 --halo-steps 1", true);
  EXPECT_GT(handOffs(lastRun_), 0) << lastRun_;
}

// Every rank builds the field: the gradient vector and auto's frame velocity (the mean over the
// domain, summed in the same order whatever the threads) are the same bits on each.
TEST_F(MpiTraceTest, DerivedVectorsOverSeeds) {
  expectRanksAgree(
      "trace builtin:cloud --backend cpu --count 50 --steps 300 --vector=-grad\\(dens\\) "
      "--frame-velocity auto",
      {2, 3});
}

// More ranks than seeds: some ranks trace nothing.
TEST_F(MpiTraceTest, RanksWithoutSeeds) {
  expectRanksAgree("trace builtin:cloud --backend cpu --count 2 --steps 300", {3});
}

// Two ranks on this host, free to run on every core (--bind-to none), take half of its cores
// each for their parallel loops (one each on two cores), and the report says so.
TEST_F(MpiTraceTest, RanksShareTheHostsCores) {
  const testing::Outcome run =
      mpirun(2, "trace builtin:rotation --backend cpu --count 8 --steps 20 --out " + path("t.vtp"));
  ASSERT_EQ(run.status, 0) << run.output;
  const std::string marker = "on the CPU reference (";
  const std::size_t at = run.output.find(marker);
  ASSERT_NE(at, std::string::npos) << run.output;
  const unsigned threads = unsigned(std::stoul(run.output.substr(at + marker.size())));
  cpu_set_t set;
  CPU_ZERO(&set);
  ASSERT_EQ(sched_getaffinity(0, sizeof(set), &set), 0);
  const unsigned usable = unsigned(CPU_COUNT(&set));
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  // Ranks already bound to fewer cores than the host has keep those.
  EXPECT_EQ(threads, usable < cores ? usable : std::max(1u, usable / 2)) << run.output;
}

class MpiGpuTraceTest : public MpiTraceTest, public ::testing::WithParamInterface<std::string> {
 protected:
  // `arguments` on one validated process and on `ranks` validated ranks; returns the ranks'
  // output.
  std::string expectValidatedRanksAgree(const std::string& arguments, const std::string& ranked,
                                        int ranks) {
    const testing::Outcome single =
        testing::runAmrstream(arguments + " --out " + path("one.vtp"), "AMRSTREAM_VALIDATION=1");
    EXPECT_EQ(single.status, 0) << single.output;
    const testing::Outcome run =
        mpirun(ranks, arguments + ranked + " --out " + path("ranks.vtp"), true);
    EXPECT_EQ(run.status, 0) << run.output;
    if (single.status == 0 && run.status == 0)
      expectSameTraces(output::readVtpTraces(path("one.vtp")),
                       output::readVtpTraces(path("ranks.vtp")));
    return run.output;
  }
};

TEST_P(MpiGpuTraceTest, RanksEqualOneProcess) {
  expectValidatedRanksAgree(
      "trace builtin:cloud --backend " + GetParam() + " --count 96 --steps 500", "", 2);
}

// Rebalanced rounds on each GPU backend: lines handed between the ranks' GPUs between rounds.
TEST_P(MpiGpuTraceTest, RebalancedRoundsEqualOneProcess) {
  const std::string output = expectValidatedRanksAgree(
      "trace builtin:cloud --backend " + GetParam() + " --count 96 --steps 500",
      " --rebalance-steps 60", 3);
  EXPECT_GT(linesHandedOn(output), 0) << output;
}

// Over data on each GPU backend (lavapipe, validation layers on every rank), against one process
// on the same backend: lines handed between ranks' GPUs many times.
TEST_P(MpiGpuTraceTest, OverDataEqualsOneProcess) {
  const std::string output =
      expectValidatedRanksAgree("trace builtin:rotation --backend " + GetParam() +
                                    " --count 30 --steps 1200 --point-data none",
                                " --distribute data", 3);
  EXPECT_THAT(output, HasSubstr("device     MiB per rank"));
}

// The same across the faces of a periodic box.
TEST_P(MpiGpuTraceTest, OverDataOnAPeriodicBoxEqualsOneProcess) {
  expectValidatedRanksAgree("trace builtin:abc --backend " + GetParam() +
                                " --count 12 --steps 400 --step-mode arc --step-size 1 "
                                "--point-data none --halo-steps 2",
                            " --distribute data", 3);
}

// Rk45 steps and the linear interpolant (its gradients) over data, on the device.
TEST_P(MpiGpuTraceTest, OverDataWithRk45AndTheLinearInterpolant) {
  expectValidatedRanksAgree("trace builtin:rotation --backend " + GetParam() +
                                " --count 12 --steps 500 --integrator rk45 --max-step 0.25 "
                                "--interpolant linear --point-data none",
                            " --distribute data", 3);
}

INSTANTIATE_TEST_SUITE_P(Backends, MpiGpuTraceTest,
                         ::testing::Values("rayquery", "pipeline", "compute"));

// One rank of three reads a truncated copy of the dataset (an MPMD launch): every rank ends,
// rank 0 prints that rank's error once, the exit status is bad input's, and no .vtp is written.
TEST_F(MpiTraceTest, ARankThatFailsEndsEveryRank) {
  ASSERT_EQ(testing::runAmrstream("gen rotation --levels 2 --out " + path("good")).status, 0);
  for (const std::string suffix : {".cells", ".vely.scalars", ".velz.scalars"})
    std::filesystem::copy_file(path("good" + suffix), path("bad" + suffix));
  {
    std::ifstream in(path("good.exa"));
    std::ofstream out(path("bad.exa"));
    for (std::string line; std::getline(in, line);) {
      for (std::size_t at; (at = line.find("good.")) != std::string::npos;)
        line.replace(at, 5, "bad.");
      out << line << '\n';
    }
    std::ofstream truncated(path("bad.velx.scalars"), std::ios::binary);
    truncated << std::string(1000, '\0');
  }
  for (const std::string out : {"out.vtp", "out.pvtp --pieces"}) {
    SCOPED_TRACE(out);
    const std::string options = " --backend cpu --count 32 --out " + path(out);
    const testing::Outcome run =
        testing::runAmrstream("trace " + path("good.exa") + options + " : -np 1 " +
                                  AMRSTREAM_BINARY + " trace " + path("bad.exa") + options,
                              "timeout 120 env " + launcher(2));
    EXPECT_EQ(run.status, 2) << run.output;
    EXPECT_THAT(run.output, HasSubstr("amrstream: error: rank 2 of 3: "));
    EXPECT_THAT(run.output, HasSubstr("bad.velx.scalars: holds 1000 bytes"));
    EXPECT_EQ(run.output.find("amrstream: error"), run.output.rfind("amrstream: error"));
    for (const char* file : {"out.vtp", "out.pvtp", "out_0.vtp", "out_1.vtp", "out_2.vtp"})
      EXPECT_FALSE(std::filesystem::exists(path(file))) << file;
  }
}

// A rank that cannot start its command (an MPMD launch whose second rank has a bad option, a
// seeds file missing on its node, an option it does not know, or another command) ends every rank
// with that rank's error, said once, instead of leaving rank 0 waiting at its first collective.
TEST_F(MpiTraceTest, ARankThatCannotStartEndsEveryRank) {
  const std::string trace =
      "trace builtin:rotation --levels 2 --root-blocks 1 --target-cells "
      "600 --backend cpu --count 4 --steps 10 --out " +
      path("out.vtp");
  const struct {
    std::string second, error;
  } cases[] = {
      {trace + " --count 0", "rank 1 of 2: --count: 0 is outside the range 1 to 2147483647"},
      {trace + " --seeds " + path("absent.txt"), "rank 1 of 2: --seeds: "},
      {trace + " --no-such-option", "rank 1 of 2: unknown option --no-such-option"},
      {"info builtin:rotation",
       "the ranks run different commands: rank 0 of 2 `trace`, "
       "rank 1 of 2 `info`"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.second);
    const testing::Outcome run = testing::runAmrstream(
        trace + " : -np 1 " + AMRSTREAM_BINARY + " " + c.second, "timeout 120 env " + launcher(1));
    EXPECT_NE(run.status, 0) << run.output;
    EXPECT_NE(run.status, 124) << "the ranks waited until the timeout:\n" << run.output;
    EXPECT_THAT(run.output, HasSubstr("amrstream: error: " + c.error));
    EXPECT_EQ(run.output.find("amrstream: error"), run.output.rfind("amrstream: error"));
    EXPECT_FALSE(std::filesystem::exists(path("out.vtp")));
  }
  // The same bad option on every rank is said once, without a rank's name, as in one process.
  const testing::Outcome same =
      testing::runAmrstream(trace + " --count 0", "timeout 120 env " + launcher(2));
  EXPECT_EQ(same.status, 2) << same.output;
  EXPECT_THAT(same.output, HasSubstr("amrstream: error: --count: 0 is outside the range"));
  EXPECT_EQ(same.output.find("amrstream: error"), same.output.rfind("amrstream: error"));
}

TEST_F(MpiTraceTest, BenchRowsOverRanksTakeTheStepsOfOneProcess) {
  // A row of 2 particles leaves a rank of 3 with none (and no kernel time to take part with).
  const std::string arguments =
      "bench builtin:cloud --backends cpu,compute --particles 2,300 --steps 200 --json ";
  const testing::Outcome single = testing::runAmrstream(arguments + path("one.json"));
  ASSERT_EQ(single.status, 0) << single.output;
  const testing::Outcome run = mpirun(3, arguments + path("three.json"));
  ASSERT_EQ(run.status, 0) << run.output;
  EXPECT_THAT(run.output,
              HasSubstr("ranks      3: each row's particles in blocks of the Morton order"));
  const auto json = [&](const std::string& name) {
    return nlohmann::json::parse(std::ifstream(path(name)));
  };
  const nlohmann::json one = json("one.json"), three = json("three.json");
  EXPECT_EQ(one["ranks"], 1);
  EXPECT_EQ(three["ranks"], 3);
  ASSERT_EQ(one["rows"].size(), 8u);  // 2 backends x 2 modes x 2 counts
  ASSERT_EQ(three["rows"].size(), one["rows"].size());
  for (std::size_t i = 0; i < one["rows"].size(); ++i) {
    SCOPED_TRACE("row " + std::to_string(i));
    for (const char* key : {"backend", "mode", "particles", "steps"})
      EXPECT_EQ(three["rows"][i][key], one["rows"][i][key]) << key;
  }
}

// --distribute data: each rank holds its part of space and a halo, lines are handed on as they
// leave a part, and rank 0 joins them: one process's file, bit for bit.
class MpiDataTraceTest : public MpiTraceTest {
 protected:
  std::string expectDataRanksAgree(const std::string& arguments,
                                   std::initializer_list<int> rankCounts) {
    return expectRanksAgree(arguments + " --distribute data", rankCounts, arguments);
  }
};

// Circles about the middle cross the parts' faces again and again.
TEST_F(MpiDataTraceTest, CirclesCrossingThePartsManyTimes) {
  const std::string output = expectDataRanksAgree(
      "trace builtin:rotation --backend cpu --count 40 --steps 2500 "
      "--point-data none",
      {2, 3, 5});
  // 80 lines handed on hundreds of times.
  EXPECT_GT(handOffs(output), 100) << output;
}

// A halo of one step: lines are handed on after the first step that leaves the part. A wide
// halo: they wander far past the faces first. And rounds cut short by a small memory budget,
// which pause lines inside the parts.
TEST_F(MpiDataTraceTest, NarrowAndWideHalosAndShortRounds) {
  const std::string one = "trace builtin:cloud --backend cpu --count 60 --steps 500";
  for (const char* more : {" --halo-steps 1", " --halo-steps 12", " --memory-budget 20K"}) {
    SCOPED_TRACE(more);
    expectRanksAgree(one + " --distribute data" + more, {3}, one);
  }
}

// Steps of three cells: a step past a face samples beyond the cells the part itself needs (with
// a halo of the margin and two cells, without a step's reach, these differ from one process).
TEST_F(MpiDataTraceTest, LongStepsPastTheFaces) {
  for (const char* halo : {" --halo-steps 1", " --halo-steps 2"}) {
    SCOPED_TRACE(halo);
    const std::string one =
        "trace builtin:rotation --backend cpu --count 60 --steps 500 "
        "--step-mode arc --step-size 3 --point-data none";
    expectRanksAgree(one + " --distribute data" + halo, {2, 3}, one);
  }
}

// The ABC flow on its periodic box: lines leave through every face and come back through the
// opposite one, into other ranks' parts; samples near a face reach the cells on the other side.
TEST_F(MpiDataTraceTest, PeriodicAxesAcrossTheParts) {
  const std::string output = expectDataRanksAgree(
      "trace builtin:abc --backend cpu --count 40 --steps 800 --step-mode arc "
      "--step-size 1 --vorticity --halo-steps 2",
      {2, 3, 4});
  EXPECT_GT(handOffs(output), 0) << output;
}

TEST_F(MpiDataTraceTest, BothDirectionsWithPointDataAndVorticity) {
  expectDataRanksAgree("trace builtin:cloud --backend cpu --count 100 --steps 600 --vorticity",
                       {2, 3});
}

TEST_F(MpiDataTraceTest, CellAndTimeModesAndEndpointsOnly) {
  expectDataRanksAgree(
      "trace builtin:cloud --backend cpu --count 80 --step-mode cell "
      "--direction forward",
      {3});
  expectDataRanksAgree(
      "trace builtin:swirl --backend cpu --count 80 --step-mode time "
      "--integrator rk2 --endpoints-only",
      {2});
}

// Seeds on every plane of finest cells across the domain (512 finest cells wide), the parts'
// faces among them: lines of no step end on the faces, the others start there.
TEST_F(MpiDataTraceTest, LinesThatStartAndEndOnTheFaces) {
  for (const char* steps : {"0", "3"})
    expectDataRanksAgree(std::string("trace builtin:rotation --backend cpu --point-data none "
                                     "--seed-line 0,0.3,0.5,1,0.3,0.5 --count 513 --steps ") +
                             steps,
                         {2, 3});
}

// Rk45 over data: steps of varying size, each trying up to `--max-step`, whose stages may sample
// much farther than a step moves (the halo allows for it); and the cloud's level jumps.
TEST_F(MpiDataTraceTest, Rk45StepsAcrossTheParts) {
  const std::string output = expectDataRanksAgree(
      "trace builtin:rotation --backend cpu --count 40 --steps 600 "
      "--integrator rk45 --step-size 0.1 --max-step 0.3 --point-data none",
      {2, 3});
  EXPECT_GT(handOffs(output), 10) << output;
  expectDataRanksAgree(
      "trace builtin:cloud --backend cpu --count 60 --steps 300 "
      "--integrator rk45 --max-step 0.3 --halo-steps 2",
      {3});
}

// The linear interpolant over data, with point data and vorticity (their gradients too): the
// cells a sample reaches have every face neighbour their gradients were fitted to.
TEST_F(MpiDataTraceTest, LinearInterpolantAcrossTheParts) {
  expectDataRanksAgree(
      "trace builtin:cloud --backend cpu --count 80 --steps 500 "
      "--interpolant linear --vorticity --halo-steps 1",
      {2, 3});
}

// A gradient vector over data: its values near a part's faces are fitted to cells beyond them,
// which the parts keep (twice as far with the linear interpolant, whose gradients of the
// gradient fit their neighbours' in turn). The frame velocity auto over a seed box off the axis
// of the rotation, (0, pi/2, 0): every rank finds it over the whole box.
TEST_F(MpiDataTraceTest, DerivedVectorsAcrossTheParts) {
  expectDataRanksAgree(
      "trace builtin:cloud --backend cpu --count 60 --steps 300 --vector=-grad\\(dens\\) "
      "--halo-steps 1",
      {2, 3});
  expectDataRanksAgree(
      "trace builtin:cloud --backend cpu --count 60 --steps 300 --vector 'grad(dens)' "
      "--interpolant linear --halo-steps 1",
      {3});
  const std::string output = expectDataRanksAgree(
      "trace builtin:rotation --backend cpu --count 40 --steps 800 --point-data none "
      "--frame-velocity auto --seed-box 0.5,0.25,0.25,1,0.75,0.75",
      {2, 3});
  EXPECT_THAT(output, HasSubstr("frame      vel relative to a frame moving at ("));
  EXPECT_GT(handOffs(output), 0) << output;
}

// What a run over data printed of the values each rank read ("read       each rank its part's
// values: 48 / 64 of 73 boxes; ..."): each rank's pieces, then the whole's; empty when it
// printed none.
std::vector<long> piecesRead(const std::string& output) {
  const std::string label = "each rank its part's values: ";
  std::size_t at = output.find(label);
  if (at == std::string::npos) return {};
  std::vector<long> counts;
  at += label.size();
  std::istringstream line(output.substr(at, output.find(';', at) - at));
  std::string word;
  while (line >> word)
    if (std::isdigit(static_cast<unsigned char>(word[0]))) counts.push_back(std::stol(word));
  return counts;
}

// FLASH, AMReX and Enzo outputs over data: each rank reads the values of the blocks, boxes or
// grids near its part alone (the first pass lays the cells out from the metadata), and the
// ranks choose density seeds together from the cells each owns (weighted by it on FLASH's):
// one process's file, bit for bit, while some rank reads less than all.
TEST_F(MpiDataTraceTest, RealInputsEachRankReadingItsPart) {
  const std::filesystem::path real(AMRSTREAM_REAL_DATA_DIR);
  struct Case {
    std::filesystem::path input;
    std::string options;
    std::initializer_list<int> ranks;
  };
  const Case cases[] = {
      {real / "flash-2d-nanowire" / "nanowire_arrayhdf5_plt_cnt_0100",
       "--vector tele,tion,depo --count 300 --steps 500 --seed-density dens --seed-weighted",
       {2, 4}},
      {real / "amrex-pelelmex-3d" / "example_plt_3d",
       "--count 200 --steps 300 --seed-density density --point-data density,temp",
       {3, 5}},
      {real / "enzo-moving7" / "DD0010" / "moving7_0010",
       "--count 200 --steps 1500 --seed-density Density --interpolant linear --vorticity",
       {5}},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.input.string());
    if (!std::filesystem::exists(c.input)) {
      std::cout << "skipped: real data " << c.input << " is absent\n";
      continue;
    }
    const std::string output =
        expectDataRanksAgree("trace " + c.input.string() + " --backend cpu " + c.options, c.ranks);
    const std::vector<long> counts = piecesRead(output);
    ASSERT_EQ(counts.size(), std::size_t(*std::prev(c.ranks.end()) + 1)) << output;
    EXPECT_LT(*std::min_element(counts.begin(), counts.end() - 1), counts.back()) << output;
  }
  // Cell mode: the ranks find the fastest vector together, as a step's reach grows with it.
  // Long steps and a halo of one step (a reach from a tenth of the fastest vector fails here).
  const std::filesystem::path enzo = real / "enzo-moving7" / "DD0010" / "moving7_0010";
  if (std::filesystem::exists(enzo)) {
    const std::string output = expectDataRanksAgree(
        "trace " + enzo.string() +
            " --backend cpu --count 200 --steps 300 --seed-density Density --step-mode cell "
            "--step-size 3 --halo-steps 1",
        {5});
    EXPECT_EQ(piecesRead(output).size(), 6u) << output;
  }
  // In time mode the default step depends on the fastest vector: every rank reads the whole.
  const std::filesystem::path amrex = real / "amrex-pelelmex-3d" / "example_plt_3d";
  if (!std::filesystem::exists(amrex)) return;
  const std::string output = expectDataRanksAgree(
      "trace " + amrex.string() + " --backend cpu --count 50 --steps 200 --step-mode time", {2});
  EXPECT_THAT(output, HasSubstr("every rank the whole input: in time mode"));
}

// On an input each rank reads its part of: a given frame velocity in cell mode, where the ranks
// find the fastest vector relative to the frame together, still reads parts; a gradient vector
// or auto's frame velocity makes every rank read the whole, saying why.
TEST_F(MpiDataTraceTest, RealInputWithDerivedVectors) {
  const std::filesystem::path enzo =
      std::filesystem::path(AMRSTREAM_REAL_DATA_DIR) / "enzo-moving7" / "DD0010" / "moving7_0010";
  if (!std::filesystem::exists(enzo)) GTEST_SKIP() << "real data " << enzo << " is absent";
  const std::string trace =
      "trace " + enzo.string() + " --backend cpu --count 100 --steps 300 --seed-density Density ";
  std::string output = expectDataRanksAgree(
      trace + "--step-mode cell --step-size 3 --halo-steps 1 --frame-velocity 0.6,0.6,0.6", {3});
  EXPECT_EQ(piecesRead(output).size(), 4u) << output;
  output = expectDataRanksAgree(trace + "--frame-velocity auto", {3});
  EXPECT_THAT(output, HasSubstr("every rank the whole input: the frame velocity auto is the mean "
                                "over the whole seeding region"));
  output = expectDataRanksAgree(trace + "--vector=-grad\\(Temperature\\)", {3});
  EXPECT_THAT(output, HasSubstr("every rank the whole input: a gradient vector at a part's edge"));
}

// A bad value in a box that some ranks read and others do not: every rank ends with the error of
// the lowest failing rank, also when the ranks would have chosen density seeds together, and no
// file is written.
TEST_F(MpiDataTraceTest, ABadValueInOneRanksWindowEndsEveryRank) {
  const std::filesystem::path real =
      std::filesystem::path(AMRSTREAM_REAL_DATA_DIR) / "amrex-pelelmex-3d" / "example_plt_3d";
  if (!std::filesystem::exists(real)) GTEST_SKIP() << "real data " << real << " is absent";
  const std::filesystem::path copy = dir_ / "plt";
  std::filesystem::copy(real, copy, std::filesystem::copy_options::recursive);
  // The first value (x_velocity) of the finest box at the domain's upper corner becomes NaN:
  // some of the 5 ranks read it, others do not.
  bool found = false;
  for (const auto& entry : std::filesystem::directory_iterator(copy / "Level_2")) {
    if (entry.path().filename().string().rfind("Cell_D", 0) != 0) continue;
    std::fstream fab(entry.path(), std::ios::in | std::ios::out | std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(fab)), std::istreambuf_iterator<char>());
    const std::size_t header = bytes.find("((24,24,24) (31,31,31) (0,0,0))");
    if (header == std::string::npos) continue;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    fab.seekp(std::streamoff(bytes.find('\n', header) + 1));
    fab.write(reinterpret_cast<const char*>(&nan), sizeof nan);
    found = true;
  }
  ASSERT_TRUE(found);
  // Density seeds, which the ranks choose together after reading; a seed grid; and cell mode,
  // where the ranks first read the parts of a first cut to find the fastest vector together.
  for (const std::string seeds :
       {"--seed-density density", "--seed-grid 4,4,4", "--seed-grid 4,4,4 --step-mode cell"}) {
    SCOPED_TRACE(seeds);
    const testing::Outcome run = testing::runAmrstream(
        "trace " + copy.string() + " --backend cpu --steps 100 --distribute data " + seeds +
            " --out " + path("out.vtp"),
        "timeout 120 env " + launcher(5));
    EXPECT_EQ(run.status, 2) << run.output;
    EXPECT_THAT(run.output, HasSubstr("amrstream: error: rank "));
    EXPECT_THAT(run.output, HasSubstr(" of 5: "));
    EXPECT_THAT(run.output, HasSubstr("variable 'x_velocity' at level-2 cell (24, 24, 24) is"));
    EXPECT_EQ(run.output.find("amrstream: error"), run.output.rfind("amrstream: error"));
    EXPECT_FALSE(std::filesystem::exists(path("out.vtp")));
  }
}

}  // namespace
}  // namespace amrstream
