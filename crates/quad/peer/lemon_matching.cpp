// Peer benchmark: LEMON's MaxMatching (Edmonds' blossom algorithm, LEMON 1.3) on a dual graph
// exported by `cargo run --release -p surftopo-quad --example quad_tables -- --lemon ...` (or
// `--example open_peers`), or (`--weighted`) LEMON's MaxWeightedPerfectMatching on a dual graph
// with integer edge weights exported by `... --example quality_tables -- --lemon ...`, or
// (`--maximum-weighted`) LEMON's MaxWeightedMatching (a matching of greatest weight, of any
// size) on a dual graph with integer weights exported by `... --example open_peers`, whose
// weights `B - cost` with `B` above any matching's total cost make the heaviest matching a
// maximum one of least cost.
//
// Usage: lemon_matching [--weighted | --maximum-weighted] DUAL_GRAPH.bin [REPEAT]
// Input (binary, little-endian): u32 node_count, u32 edge_count, then edge_count pairs of u32
// node ids; with a weighted mode, then edge_count i64 weights. MaxMatching::run() (greedy
// initialisation + augmentations), or MaxWeightedPerfectMatching::run() /
// MaxWeightedMatching::run() (fractional initialisation + Edmonds' primal-dual steps, exact
// integer duals for an integer weight type), is timed REPEAT times (default 1) on fresh objects.
// Output: one JSON line with the matching size (and, weighted, whether it is perfect and its
// weight), the seconds to build the SmartGraph, the minimum and median wall seconds of run(),
// the figure compared with surftopo's time, and the mean thread CPU seconds of run() (robust to
// a loaded machine). Not part of CI.
#include <lemon/matching.h>
#include <lemon/smart_graph.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <ctime>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

int main(int argc, char** argv) {
  const bool perfect_weighted = argc >= 2 && std::string(argv[1]) == "--weighted";
  const bool maximum_weighted = argc >= 2 && std::string(argv[1]) == "--maximum-weighted";
  const bool weighted = perfect_weighted || maximum_weighted;
  if (weighted) {
    --argc;
    ++argv;
  }
  if (argc != 2 && argc != 3) {
    std::fprintf(stderr, "usage: %s [--weighted | --maximum-weighted] DUAL_GRAPH.bin [REPEAT]\n",
                 argv[0]);
    return 2;
  }
  const int repeat = argc == 3 ? std::max(1, std::atoi(argv[2])) : 1;
  std::FILE* file = std::fopen(argv[1], "rb");
  if (!file) {
    std::perror(argv[1]);
    return 1;
  }
  std::uint32_t header[2];
  if (std::fread(header, sizeof(std::uint32_t), 2, file) != 2) {
    std::fprintf(stderr, "%s: truncated header\n", argv[1]);
    return 1;
  }
  const std::uint32_t n = header[0], m = header[1];
  std::vector<std::uint32_t> ends(2 * static_cast<std::size_t>(m));
  if (std::fread(ends.data(), sizeof(std::uint32_t), ends.size(), file) != ends.size()) {
    std::fprintf(stderr, "%s: truncated edge list\n", argv[1]);
    return 1;
  }
  std::vector<long long> weights(weighted ? m : 0);
  static_assert(sizeof(long long) == 8, "i64 weights");
  if (weighted && std::fread(weights.data(), 8, m, file) != m) {
    std::fprintf(stderr, "%s: truncated weights\n", argv[1]);
    return 1;
  }
  std::fclose(file);
  for (std::uint32_t v : ends) {
    if (v >= n) {
      std::fprintf(stderr, "%s: node %u out of range\n", argv[1], v);
      return 1;
    }
  }

  using Clock = std::chrono::steady_clock;
  const auto t0 = Clock::now();
  lemon::SmartGraph graph;
  graph.reserveNode(n);
  graph.reserveEdge(m);
  std::vector<lemon::SmartGraph::Node> nodes(n);
  for (std::uint32_t v = 0; v < n; ++v) nodes[v] = graph.addNode();
  for (std::uint32_t e = 0; e < m; ++e) graph.addEdge(nodes[ends[2 * e]], nodes[ends[2 * e + 1]]);
  const auto t1 = Clock::now();
  const double build = std::chrono::duration<double>(t1 - t0).count();
  std::vector<double> runs;
  double cpu = 0.0;
  int size = 0;
  auto thread_cpu = [] {
    timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
  };
  if (maximum_weighted) {
    lemon::SmartGraph::EdgeMap<long long> weight(graph);
    for (std::uint32_t e = 0; e < m; ++e) weight[graph.edgeFromId(e)] = weights[e];
    long long total = 0;
    for (int r = 0; r < repeat; ++r) {
      const double c0 = thread_cpu();
      const auto s0 = Clock::now();
      lemon::MaxWeightedMatching<lemon::SmartGraph, lemon::SmartGraph::EdgeMap<long long>>
          matching(graph, weight);
      matching.run();
      const auto s1 = Clock::now();
      cpu += thread_cpu() - c0;
      runs.push_back(std::chrono::duration<double>(s1 - s0).count());
      total = matching.matchingWeight();
      size = matching.matchingSize();
    }
    std::sort(runs.begin(), runs.end());
    std::printf("{\"nodes\":%u,\"edges\":%u,\"matching_size\":%d,\"matching_weight\":%lld,"
                "\"build_seconds\":%.6f,\"run_seconds\":%.6f,\"median_run_seconds\":%.6f,"
                "\"cpu_run_seconds\":%.6f,\"repeat\":%d}\n",
                n, m, size, total, build, runs.front(), runs[runs.size() / 2], cpu / repeat,
                repeat);
    return 0;
  }
  if (perfect_weighted) {
    lemon::SmartGraph::EdgeMap<long long> weight(graph);
    for (std::uint32_t e = 0; e < m; ++e) weight[graph.edgeFromId(e)] = weights[e];
    bool perfect = false;
    long long total = 0;
    for (int r = 0; r < repeat; ++r) {
      const double c0 = thread_cpu();
      const auto s0 = Clock::now();
      lemon::MaxWeightedPerfectMatching<lemon::SmartGraph, lemon::SmartGraph::EdgeMap<long long>>
          matching(graph, weight);
      perfect = matching.run();
      const auto s1 = Clock::now();
      cpu += thread_cpu() - c0;
      runs.push_back(std::chrono::duration<double>(s1 - s0).count());
      total = perfect ? matching.matchingWeight() : 0;
      size = 0;
      if (perfect)
        for (std::uint32_t e = 0; e < m; ++e) size += matching.matching(graph.edgeFromId(e));
    }
    std::sort(runs.begin(), runs.end());
    std::printf("{\"nodes\":%u,\"edges\":%u,\"perfect\":%s,\"matching_size\":%d,"
                "\"matching_weight\":%lld,\"build_seconds\":%.6f,\"run_seconds\":%.6f,"
                "\"median_run_seconds\":%.6f,\"cpu_run_seconds\":%.6f,\"repeat\":%d}\n",
                n, m, perfect ? "true" : "false", size, total, build, runs.front(),
                runs[runs.size() / 2], cpu / repeat, repeat);
    return 0;
  }
  for (int r = 0; r < repeat; ++r) {
    const double c0 = thread_cpu();
    const auto s0 = Clock::now();
    lemon::MaxMatching<lemon::SmartGraph> matching(graph);
    matching.run();
    const auto s1 = Clock::now();
    cpu += thread_cpu() - c0;
    runs.push_back(std::chrono::duration<double>(s1 - s0).count());
    size = matching.matchingSize();
  }
  std::sort(runs.begin(), runs.end());
  std::printf("{\"nodes\":%u,\"edges\":%u,\"matching_size\":%d,\"build_seconds\":%.6f,"
              "\"run_seconds\":%.6f,\"median_run_seconds\":%.6f,\"cpu_run_seconds\":%.6f,"
              "\"repeat\":%d}\n",
              n, m, size, build, runs.front(), runs[runs.size() / 2], cpu / repeat, repeat);
  return 0;
}
