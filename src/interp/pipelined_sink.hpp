#pragma once
// Hands the element stream to a worker thread, so that reading and interpreting the program (the
// calling thread) overlaps with what follows it (compensation, compressor, smoothing, planner on
// the worker). The control does the same: its preprocessing runs ahead of the main run. On a
// two-core machine this makes `drycut run` on a CAM program up to ~1.8x faster in wall time;
// the element stream, and so every planned number, is the same as without it.
//
// How it keeps the sequential contract (an alarm stops the run at the block that caused it):
// - Elements go over in batches of kBatch (one lock per batch, not per element), at most
//   kBatchesInFlight of them queued: the producer blocks when the worker falls behind, so memory
//   stays bounded and the producer runs at most kBatch·(kBatchesInFlight + 1) elements ahead.
//   Batches are large because the faster thread sleeps and is woken about once per batch, and
//   on a virtual machine a sleep and wake-up cost ~20 µs of CPU: with batches of 128 a G1
//   program of 1 M blocks switched threads ~7600 times, with 1024 ~970 (perf stat, 6 runs:
//   1.45 -> 1.33 s CPU, 0.84 -> 0.78 s wall; ~1 MB more memory, more on spline programs).
// - With every element the producer's MARK is taken (a snapshot the caller defines: how many
//   warnings it had reported, how many blocks it had run). When the downstream raises an alarm on
//   an element, the worker stops, keeps the alarm and that element's mark, and drops the rest;
//   the producer's next consume() throws the alarm, so the interpreter stops as it would have
//   (only a few blocks later). The caller then cuts its own records back to the mark: warnings
//   of the blocks the producer ran ahead are not the run's (app/program_pipeline.cpp cuts back
//   warnings, blocks, lines and programs used; the set of commands used may hold a few more).
//   An alarm raised downstream without a location gets the failing element's block.
// - An alarm of the producer itself comes from a later block than every element it handed over:
//   drain() lets the worker finish those first, and an alarm they raise takes precedence.
// - Any other exception (I/O, bad_alloc) on the worker is rethrown to the producer as it is.
//
// Consumed batches go back to the producer, which refills them: their vectors keep their
// capacity (a fresh 128-element vector is a large block whose malloc and free consolidate the
// allocator's bins), and what the downstream left in the moved-from elements (the planner hands
// back the block reference and curve of the elements it retired) goes back slot by slot in the
// element the producer hands over next, in its place: the interpreter writes the next block
// text and line into them (Interpreter::emit), so a block allocates neither.
#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <deque>
#include <exception>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>
#include <vector>

#include "interp/path_element.hpp"
#include "machine/alarm.hpp"

namespace drycut::interp {

// MarkFn: the callable that takes the mark (a lambda's own type saves an indirect call per element).
template <class Mark, class MarkFn = std::function<Mark()>>
class PipelinedSink final : public ElementSink {
 public:
  static constexpr size_t kBatch = 1024;
  static constexpr size_t kBatchesInFlight = 4;

  struct Failure {
    AlarmError error;
    Mark mark;  // the producer's mark when it handed over the element that raised it
  };

  PipelinedSink(ElementSink& downstream, MarkFn mark)
      : downstream_(downstream), mark_(std::move(mark)), worker_([this] { work(); }) {}
  PipelinedSink(const PipelinedSink&) = delete;
  PipelinedSink& operator=(const PipelinedSink&) = delete;
  ~PipelinedSink() override { stop_worker(); }

  void consume(PathElement&& element) override {
    if (failed_.load(std::memory_order_acquire)) {
      // Thrown once; what the producer still sends while it winds down (its finish) is dropped.
      if (std::exchange(delivered_, true)) return;
      rethrow_fatal();
      throw failure_->error;
    }
    put(std::move(element));
    if (batch_.count >= kBatch) hand_over();
  }

  // Hands over what is left, waits for the worker to end, then finishes the downstream on this
  // thread. After a downstream alarm the downstream is still finished (it hands on what it holds,
  // nothing written is lost); an alarm of that flush is a follow-up and dropped.
  void finish() override {
    hand_over();
    stop_worker();
    rethrow_fatal();
    if (failure_) {
      try {
        downstream_.finish();
      } catch (const AlarmError&) {
      }
      return;
    }
    downstream_.finish();
  }

  // Waits until the worker has consumed every element handed to it so far (the partial batch
  // included). Afterwards failure() says whether one of them raised an alarm.
  void drain() {
    hand_over();
    std::unique_lock lock(mutex_);
    idle_.wait(lock, [this] { return queue_.empty() && !busy_; });
    lock.unlock();
    if (failed_.load(std::memory_order_acquire)) delivered_ = true;
    rethrow_fatal();
  }

  // The downstream alarm that stopped the stream, once the worker has stopped on it.
  const std::optional<Failure>& failure() const { return failure_; }

 private:
  struct Batch {
    // Elements [0, count) are handed over; those after them are moved-from leftovers of the
    // batch's earlier round, overwritten as it is refilled.
    std::vector<PathElement> elements;
    std::vector<Mark> marks;
    size_t count = 0;
  };

  void put(PathElement&& element) {
    if (batch_.count < batch_.elements.size()) {
      PathElement& slot = batch_.elements[batch_.count];
      geometry::CurvePtr curve = std::move(slot.curve);
      // The block text's buffer goes back without a step of its own: a std::string moved into
      // one with a heap buffer leaves that buffer in the moved-from string (libstdc++).
      slot = std::move(element);
      element.curve = std::move(curve);  // the leftover curve goes back to the producer
      batch_.marks[batch_.count] = mark_();
    } else {
      batch_.elements.push_back(std::move(element));
      batch_.marks.push_back(mark_());
    }
    ++batch_.count;
  }

  void hand_over() {
    if (batch_.count == 0 || !worker_.joinable()) return;
    std::unique_lock lock(mutex_);
    room_.wait(lock, [this] { return queue_.size() < kBatchesInFlight; });
    queue_.push_back(std::move(batch_));
    batch_ = Batch{};
    if (!spent_.empty()) {
      batch_ = std::move(spent_.back());
      spent_.pop_back();
    }
    lock.unlock();
    work_ready_.notify_one();
    batch_.count = 0;
    batch_.elements.reserve(kBatch);
    batch_.marks.reserve(kBatch);
  }

  void work() {
    for (;;) {
      Batch batch;
      {
        std::unique_lock lock(mutex_);
        work_ready_.wait(lock, [this] { return !queue_.empty() || closing_; });
        if (queue_.empty()) return;
        batch = std::move(queue_.front());
        queue_.pop_front();
        busy_ = true;
      }
      room_.notify_one();
      if (!stopped_) consume_batch(batch);
      {
        std::lock_guard lock(mutex_);
        busy_ = false;
        spent_.push_back(std::move(batch));
      }
      idle_.notify_all();
    }
  }

  void consume_batch(Batch& batch) {
    for (size_t i = 0; i < batch.count; ++i) {
      try {
        downstream_.consume(std::move(batch.elements[i]));
      } catch (const AlarmError& e) {
        failure_.emplace(Failure{located(e, batch.elements[i].source), batch.marks[i]});
        stopped_ = true;
        failed_.store(true, std::memory_order_release);
        return;
      } catch (...) {
        fatal_ = std::current_exception();
        stopped_ = true;
        failed_.store(true, std::memory_order_release);
        return;
      }
    }
  }

  // An alarm of the downstream that does not say where (a geometry stage's) belongs to the block
  // of the element it was raised on, as the interpreter would have located it sequentially.
  static AlarmError located(const AlarmError& e, const BlockRef& source) {
    if (!e.alarm().where.file.empty() || !source.file) return e;
    Alarm a = e.alarm();
    a.where = {*source.file, source.line, 0};
    a.block = source.text;
    return AlarmError(std::move(a));
  }

  void rethrow_fatal() {
    if (!failed_.load(std::memory_order_acquire)) return;
    if (auto fatal = std::exchange(fatal_, nullptr)) std::rethrow_exception(fatal);
  }

  void stop_worker() {
    if (!worker_.joinable()) return;
    {
      std::lock_guard lock(mutex_);
      closing_ = true;
    }
    work_ready_.notify_one();
    worker_.join();
  }

  ElementSink& downstream_;
  MarkFn mark_;
  Batch batch_;  // the producer's batch being filled

  bool delivered_ = false;  // the producer has been told of the failure

  std::mutex mutex_;  // guards the queue, the spent batches and the two flags after them
  std::condition_variable work_ready_, room_, idle_;
  std::deque<Batch> queue_;
  std::vector<Batch> spent_;  // consumed batches, back for the producer to refill
  bool busy_ = false, closing_ = false;

  // Written by the worker only, before it sets failed_ (release); the producer reads them after
  // seeing failed_ (acquire).
  bool stopped_ = false;  // the worker drops further batches
  std::optional<Failure> failure_;
  std::exception_ptr fatal_;
  std::atomic<bool> failed_{false};

  std::thread worker_;  // last: started after everything it uses is constructed
};

}  // namespace drycut::interp
