// A batch of RunIndexed spread over ranks (runner.h, internal::RunIndicesOnRanks).
//
// One AllGather deals the batch (rank 0 sends which indices its journal
// holds), a second gathers it, and a third agrees that rank 0 journaled the
// others' results. In the second, each rank sends one message, its status
// and every result it has (docs/reproducibility.md, "Many machines: MPI"):
//
//   U64 status (0 finished, 1 failed, 2 stopped)  U64 failing index
//   Str encoded exception  U64 results  (U64 index  Str bytes) ...
#include <fmt/format.h>

#include <optional>

#include "vahf/core/byte_fields.h"
#include "vahf/core/error.h"
#include "vahf/experiment/runner.h"

namespace vahf::experiment::internal {
namespace {

enum Status : std::uint64_t { kFinished = 0, kFailed = 1, kStopped = 2 };

constexpr char kToRun = '-';
constexpr char kJournaled = 'j';

// This rank's share: the indices still to run, dealt round-robin, so that each
// rank gets as many of every condition's cycles as the others, give or take one.
std::vector<std::size_t> Share(const std::string& mask, int rank, int size) {
  std::vector<std::size_t> mine;
  std::size_t k = 0;
  for (std::size_t i = 0; i < mask.size(); ++i)
    if (mask[i] == kToRun &&
        static_cast<int>(k++ % static_cast<std::size_t>(size)) == rank)
      mine.push_back(i);
  return mine;
}

// Runs this rank's share on its threads; returns its message. `held`: what
// rank 0's journal holds, sent with its own results.
std::string RunShare(const std::vector<std::size_t>& mine,
                     const std::vector<std::optional<std::string>>& held,
                     const RunnerOptions& options,
                     const std::function<std::string(std::size_t)>& run,
                     Journal::Batch* batch) {
  const Ranks& ranks = *options.ranks;
  std::vector<std::string> bytes(mine.size());
  std::vector<char> finished(mine.size(), 0);  // each worker writes its own slots
  std::uint64_t status = kFinished;
  std::string error;
  RunnerOptions share = options;  // its progress line counts this rank's share
  share.label =
      fmt::format("{} (rank {} of {}: {} of the {} {})", options.label, ranks.rank(),
                  ranks.size(), mine.size(), held.size(), options.unit);
  try {
    RunIndices(mine.size(), share, [&](std::size_t p) {
      bytes[p] = run(mine[p]);
      if (batch) batch->Store(mine[p], bytes[p]);
      finished[p] = 1;
    });
  } catch (const Interrupted&) {
    status = kStopped;
  } catch (const std::exception&) {
    status = kFailed;
    error = EncodeException(std::current_exception());
  }
  // A failure is at the lowest position not finished: every one below it ran
  // to the end (RunIndices).
  std::size_t failed_at = held.size();
  if (status == kFailed)
    for (std::size_t p = 0; p < mine.size() && failed_at == held.size(); ++p)
      if (!finished[p]) failed_at = mine[p];

  ByteWriter message;
  message.U64(status);
  message.U64(failed_at);
  message.Str(error);
  std::uint64_t results = 0;
  for (const std::optional<std::string>& h : held) results += h.has_value();
  for (char f : finished) results += f != 0;
  message.U64(results);
  for (std::size_t i = 0; i < held.size(); ++i)
    if (held[i]) {
      message.U64(i);
      message.Str(*held[i]);
    }
  for (std::size_t p = 0; p < mine.size(); ++p)
    if (finished[p]) {
      message.U64(mine[p]);
      message.Str(bytes[p]);
    }
  return message.Take();
}

// Every rank's message, read the same way on every rank.
struct Gathered {
  std::vector<std::optional<std::string>> out;  // by index
  std::vector<std::size_t> from;                // the rank that sent each
  std::size_t done = 0;                         // results received
  std::string failure;                          // the lowest failing index's error
  bool stopped = false;                         // a rank stopped on request
};

Gathered Read(const std::vector<std::string>& messages, std::size_t n) {
  Gathered g;
  g.out.resize(n);
  g.from.resize(n);
  std::uint64_t lowest_failure = 0;
  for (std::size_t from = 0; from < messages.size(); ++from) {
    ByteReader r(messages[from]);
    const std::uint64_t status = r.U64();
    const std::uint64_t at = r.U64();  // n: after its last index (the meter threw)
    std::string error = r.Str();
    if (status == kFailed && (g.failure.empty() || at < lowest_failure)) {
      lowest_failure = at;
      g.failure = std::move(error);
    }
    g.stopped = g.stopped || status == kStopped;
    for (std::uint64_t k = r.U64(); k > 0; --k) {
      const std::uint64_t i = r.U64();
      VAHF_CHECK(i < n && !g.out[i], "each index's result comes from one rank");
      g.out[i] = r.Str();
      g.from[i] = from;
      ++g.done;
    }
  }
  return g;
}

// What rank 0 sends first: "M" and which indices its journal holds, or "E"
// and the error opening the batch threw (a journal of another run), which
// every rank then throws instead of waiting for a rank that stopped.
std::string Deal(std::size_t n, const RunnerOptions& options,
                 std::unique_ptr<Journal::Batch>* batch,
                 std::vector<std::optional<std::string>>* held) {
  try {
    std::string mask(n, kToRun);
    if (options.journal) {
      *batch = options.journal->Begin(n, options.label);
      for (std::size_t i = 0; i < n; ++i)
        if (((*held)[i] = (*batch)->Find(i))) mask[i] = kJournaled;
    }
    return "M" + mask;
  } catch (const std::exception&) {
    return "E" + EncodeException(std::current_exception());
  }
}

}  // namespace

std::vector<std::string> RunIndicesOnRanks(
    std::size_t n, const RunnerOptions& options,
    const std::function<std::string(std::size_t)>& run) {
  const Ranks& ranks = *options.ranks;
  // Rank 0 keeps the journal; the indices it holds are read, not run.
  std::unique_ptr<Journal::Batch> batch;
  std::vector<std::optional<std::string>> held(n);
  const std::string dealt = ranks.AllGather(
      ranks.rank() == 0 ? Deal(n, options, &batch, &held) : std::string())[0];
  VAHF_CHECK(!dealt.empty(), "rank 0 deals every batch");
  if (dealt[0] == 'E') ThrowEncodedException(dealt.substr(1));
  const std::string mask = dealt.substr(1);
  VAHF_CHECK(mask.size() == n, "every rank runs the same batch");
  const std::vector<std::size_t> mine = Share(mask, ranks.rank(), ranks.size());
  std::string message = RunShare(mine, held, options, run, batch.get());
  held.clear();
  Gathered g = Read(ranks.AllGather(message), n);
  // Rank 0 journals the others' results, even those of a failed or stopped
  // batch; a refusal there (a full disk) stops every rank alike.
  AllAgree(&ranks, [&] {
    if (batch)
      for (std::size_t i = 0; i < n; ++i)
        if (g.out[i] && g.from[i] != 0) batch->Store(i, *g.out[i]);
  });
  if (!g.failure.empty()) ThrowEncodedException(g.failure);
  if (g.stopped)  // thrown alike on every rank, as every rank's own would be
    ThrowAgreed(std::make_exception_ptr(Interrupted(StoppedMessage(options, g.done, n))));
  std::vector<std::string> all;
  all.reserve(n);
  for (std::optional<std::string>& o : g.out) {
    VAHF_CHECK(o.has_value(), "every index ran on some rank");
    all.push_back(std::move(*o));
  }
  return all;
}

}  // namespace vahf::experiment::internal
