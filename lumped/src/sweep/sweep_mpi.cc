// Sweeps across MPI ranks: rank 0 deals case indices on request and puts the rows back in case
// order; every rank runs cases on its own threads. Only the thread that called run_sweep_mpi
// talks MPI (MPI_THREAD_FUNNELED); it polls (MPI_Iprobe, then a wait on a condition variable
// that a finished row ends early) instead of blocking in MPI, whose blocking calls spin a core
// that the cases need. The waits back off from 50 µs to 500 µs while nothing comes: each poll
// costs a few µs of CPU, and a fixed 100 µs poll on both ranks took ~12 % of the cases' CPU time
// (bench/README.md, issue 20); the case asked for ahead (kPrefetch) hides the latency.
//
// Messages (MPI_COMM_WORLD):
//   worker → 0  kRequest (empty)  one more case, please (a worker keeps threads + 1 asked for)
//   worker → 0  kRow (bytes)      a finished case: encode_sweep_row(index, row)
//   worker → 0  kDone (empty)     no case in hand and no request open: the worker returns
//   0 → worker  kAssign (int64)   the case to run, or −1: nothing left (the answer to a request)

#include "bearing/sweep_mpi.h"

#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <exception>
#include <map>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "bearing/sweep_row_codec.h"

namespace bearing {

namespace {

enum Tag : int { kRequest = 1, kRow = 2, kDone = 3, kAssign = 4 };

// Finished rows a worker may run ahead of the oldest unfinished one, per worker (as run_sweep).
constexpr std::size_t kWindowPerWorker = 4;
// Cases a rank asks for beyond its threads, so a thread that finishes finds the next one waiting.
constexpr int kPrefetch = 1;
// How long the MPI thread sleeps when there is nothing to do: doubling from the first to the last.
constexpr auto kPollFirst = std::chrono::microseconds(50);
constexpr auto kPollLast = std::chrono::microseconds(500);

// The wait before the next poll: back to the first after activity, else twice the last one.
std::chrono::microseconds next_wait(std::chrono::microseconds wait, bool active) {
  return active ? kPollFirst : std::min(2 * wait, kPollLast);
}

// One case, run exactly as run_sweep runs it (the same code, so the same bits).
SweepRow run_one(const SweepLoader& load, const SweepPoint& point,
                 const std::vector<SweepSave>& save) {
  SweepRow out;
  run_sweep(
      load, 1, [&](std::size_t) { return point; }, 1,
      [&](std::size_t, SweepRow&& row) { out = std::move(row); }, {}, save);
  return out;
}

// `threads`, or with 0 this node's cores shared among its ranks. Collective (every rank calls
// it, whatever its `threads`).
int threads_of_rank(int threads) {
  MPI_Comm node;
  MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
  int ranks = 1;
  MPI_Comm_size(node, &ranks);
  MPI_Comm_free(&node);
  if (threads > 0) return threads;
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  return std::max(1, cores / ranks);
}

// Rank 0: deals the cases, runs some itself, passes the rows on in case order.
class Coordinator {
 public:
  Coordinator(const SweepLoader& load, std::size_t cases,
              const std::function<SweepPoint(std::size_t)>& point,
              const std::function<void(std::size_t, SweepRow&&)>& sink,
              const SweepProgress& progress, const std::vector<SweepSave>& save, std::size_t window,
              int workers)
      : load_(load),
        cases_(cases),
        point_(point),
        save_(save),
        sink_(sink),
        progress_(progress),
        window_(window),
        workers_(workers) {}

  void run(int threads) {
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t) pool.emplace_back([this] { compute(); });
    try {
      coordinate();
    } catch (...) {
      stop();
      for (auto& t : pool) t.join();
      throw;
    }
    for (auto& t : pool) t.join();
    if (sink_error_) std::rethrow_exception(sink_error_);
  }

 private:
  bool no_more() const { return next_ >= cases_ || sink_error_ || stopped_; }

  void stop() {
    std::lock_guard<std::mutex> lock(mutex_);
    stopped_ = true;
    can_start_.notify_all();
  }

  // A thread of rank 0: takes the next case while the window allows.
  void compute() {
    for (;;) {
      std::size_t i = 0;
      {
        std::unique_lock<std::mutex> lock(mutex_);
        can_start_.wait(lock, [&] { return no_more() || next_ < handed_ + window_; });
        if (no_more()) return;
        i = next_++;
      }
      accept(i, run_one(load_, point_(i), save_));
    }
  }

  // A finished row, from any rank: passed on with every row after it that is already here.
  void accept(std::size_t i, SweepRow&& row) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (sink_error_) return;
    waiting_.emplace(i, std::move(row));
    if (progress_) progress_(++done_, cases_);
    for (auto it = waiting_.begin(); it != waiting_.end() && it->first == handed_ && !sink_error_;
         it = waiting_.erase(it), ++handed_) {
      try {
        sink_(it->first, std::move(it->second));
      } catch (...) {
        sink_error_ = std::current_exception();
      }
    }
    can_start_.notify_all();
  }

  // Answers the open requests in order while the window allows (−1 once nothing is left).
  bool serve(std::deque<int>& requests) {
    bool any = false;
    while (!requests.empty()) {
      std::int64_t i = -1;
      {
        std::lock_guard<std::mutex> lock(mutex_);
        if (!no_more()) {
          if (next_ >= handed_ + window_) break;
          i = static_cast<std::int64_t>(next_++);
        }
      }
      MPI_Send(&i, 1, MPI_INT64_T, requests.front(), kAssign, MPI_COMM_WORLD);
      requests.pop_front();
      any = true;
    }
    return any;
  }

  // Receives every message waiting; false if there was none.
  bool receive(std::deque<int>& requests, int& done_workers) {
    bool any = false;
    int flag = 0;
    MPI_Status st;
    while (MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &st) == MPI_SUCCESS &&
           flag) {
      any = true;
      int n = 0;
      MPI_Get_count(&st, MPI_BYTE, &n);
      buffer_.resize(static_cast<std::size_t>(n));
      MPI_Recv(buffer_.data(), n, MPI_BYTE, st.MPI_SOURCE, st.MPI_TAG, MPI_COMM_WORLD,
               MPI_STATUS_IGNORE);
      if (st.MPI_TAG == kRequest) {
        requests.push_back(st.MPI_SOURCE);
      } else if (st.MPI_TAG == kDone) {
        ++done_workers;
      } else if (st.MPI_TAG == kRow) {
        std::size_t i = 0;
        SweepRow row = decode_sweep_row(buffer_, i);
        if (i >= cases_) throw std::runtime_error("sweep: a rank sent a row of an unknown case");
        accept(i, std::move(row));
      } else {
        throw std::runtime_error("sweep: unexpected MPI message tag " + std::to_string(st.MPI_TAG));
      }
    }
    return any;
  }

  // The MPI loop: until every other rank has said it is done.
  void coordinate() {
    std::deque<int> requests;
    int done_workers = 0;
    auto wait = kPollFirst;
    while (done_workers < workers_) {
      const bool received = receive(requests, done_workers);
      const bool served = serve(requests);
      wait = next_wait(wait, received || served);
      if (!received && !served) {
        std::unique_lock<std::mutex> lock(mutex_);
        can_start_.wait_for(lock, wait);
      }
    }
  }

  const SweepLoader& load_;
  const std::size_t cases_;
  const std::function<SweepPoint(std::size_t)>& point_;
  const std::vector<SweepSave>& save_;  // the tables each row carries (sweep --save)
  const std::function<void(std::size_t, SweepRow&&)>& sink_;
  const SweepProgress& progress_;
  const std::size_t window_;
  const int workers_;
  std::mutex mutex_;
  std::condition_variable can_start_;  // a row came or the sweep stopped
  std::size_t next_ = 0;               // the next case to hand out
  std::size_t handed_ = 0;             // rows passed to sink (cases 0 … handed_ − 1)
  std::size_t done_ = 0;               // rows received
  std::map<std::size_t, SweepRow> waiting_;
  std::exception_ptr sink_error_;
  bool stopped_ = false;
  std::string buffer_;
};

// Ranks > 0: ask for cases, run them on `threads` threads, send the rows to rank 0.
class Worker {
 public:
  Worker(const SweepLoader& load, const std::function<SweepPoint(std::size_t)>& point,
         const std::vector<SweepSave>& save)
      : load_(load), point_(point), save_(save) {}

  void run(int threads) {
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t) pool.emplace_back([this] { compute(); });
    try {
      communicate(threads + kPrefetch);
    } catch (...) {
      quit(pool);
      throw;
    }
    quit(pool);
    MPI_Send(nullptr, 0, MPI_BYTE, 0, kDone, MPI_COMM_WORLD);
  }

 private:
  void quit(std::vector<std::thread>& pool) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      quit_ = true;
    }
    ready_.notify_all();
    for (auto& t : pool) t.join();
  }

  void compute() {
    for (;;) {
      std::size_t i = 0;
      {
        std::unique_lock<std::mutex> lock(mutex_);
        ready_.wait(lock, [&] { return quit_ || !todo_.empty(); });
        if (todo_.empty()) return;
        i = todo_.front();
        todo_.pop_front();
      }
      SweepRow row = run_one(load_, point_(i), save_);
      std::lock_guard<std::mutex> lock(mutex_);
      finished_.emplace_back(i, std::move(row));
      finished_one_.notify_one();
    }
  }

  static void request() { MPI_Send(nullptr, 0, MPI_BYTE, 0, kRequest, MPI_COMM_WORLD); }

  // Keeps `slots` cases asked for or in hand until rank 0 answers −1, then sends what is left.
  void communicate(int slots) {
    for (int s = 0; s < slots; ++s) request();
    int open = slots;  // requests not yet answered
    int in_hand = 0;   // cases received and not yet sent back
    bool stopped = false;
    std::string buffer;
    auto wait = kPollFirst;
    while (!stopped || open > 0 || in_hand > 0) {
      std::deque<std::pair<std::size_t, SweepRow>> out;
      {
        std::lock_guard<std::mutex> lock(mutex_);
        out.swap(finished_);
      }
      for (auto& [i, row] : out) {
        buffer.clear();
        encode_sweep_row(i, row, buffer);
        MPI_Send(buffer.data(), static_cast<int>(buffer.size()), MPI_BYTE, 0, kRow, MPI_COMM_WORLD);
        --in_hand;
        if (!stopped) {
          request();
          ++open;
        }
      }
      bool assigned = false;
      int flag = 0;
      while (MPI_Iprobe(0, kAssign, MPI_COMM_WORLD, &flag, MPI_STATUS_IGNORE) == MPI_SUCCESS &&
             flag) {
        std::int64_t i = -1;
        MPI_Recv(&i, 1, MPI_INT64_T, 0, kAssign, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        --open;
        assigned = true;
        if (i < 0) {
          stopped = true;
          continue;
        }
        std::lock_guard<std::mutex> lock(mutex_);
        todo_.push_back(static_cast<std::size_t>(i));
        ++in_hand;
        ready_.notify_one();
      }
      wait = next_wait(wait, !out.empty() || assigned);
      if (out.empty() && !assigned) {
        std::unique_lock<std::mutex> lock(mutex_);
        finished_one_.wait_for(lock, wait, [&] { return !finished_.empty(); });
      }
    }
  }

  const SweepLoader& load_;
  const std::function<SweepPoint(std::size_t)>& point_;
  const std::vector<SweepSave>& save_;  // the tables each row carries (sweep --save)
  std::mutex mutex_;
  std::condition_variable ready_;         // a case to run, or quit
  std::condition_variable finished_one_;  // a row to send
  std::deque<std::size_t> todo_;
  std::deque<std::pair<std::size_t, SweepRow>> finished_;
  bool quit_ = false;
};

}  // namespace

int mpi_rank() {
  int initialized = 0;
  MPI_Initialized(&initialized);
  int rank = 0;
  if (initialized) MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  return rank;
}

int mpi_size() {
  int initialized = 0;
  MPI_Initialized(&initialized);
  int size = 1;
  if (initialized) MPI_Comm_size(MPI_COMM_WORLD, &size);
  return size;
}

void run_sweep_mpi(const SweepLoader& load, std::size_t cases,
                   const std::function<SweepPoint(std::size_t)>& point, int threads,
                   const std::function<void(std::size_t, SweepRow&&)>& sink,
                   const SweepProgress& progress, const std::vector<SweepSave>& save) {
  const int size = mpi_size();
  if (size <= 1) return run_sweep(load, cases, point, threads, sink, progress, save);
  const int rank = mpi_rank();
  const int own = threads_of_rank(threads);
  // Every rank's workers, the window of rank 0's reorder buffer: collective, on every rank.
  int slots = rank == 0 ? own : own + kPrefetch;
  int all_slots = 0;
  MPI_Allreduce(&slots, &all_slots, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  if (rank == 0) {
    const std::size_t window = kWindowPerWorker * static_cast<std::size_t>(all_slots);
    Coordinator(load, cases, point, sink, progress, save, window, size - 1).run(own);
  } else {
    Worker(load, point, save).run(own);
  }
}

}  // namespace bearing
