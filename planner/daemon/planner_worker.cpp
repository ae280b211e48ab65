#include "planner/daemon/planner_worker.hpp"

#include <stdexcept>
#include <utility>

namespace ifar::planner {

PlannerWorker::PlannerWorker(Planner planner, std::function<std::int64_t()> clock, WorkerThreading threading)
    : planner_(std::move(planner)), clock_(std::move(clock)), threading_(threading)
{
  if (threading_ == WorkerThreading::OwnThread) {
    thread_ = std::thread([this] { loop(); });
  }
}

PlannerWorker::~PlannerWorker()
{
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_one();
  if (thread_.joinable()) {
    thread_.join();
  }
}

bool PlannerWorker::busy() const
{
  const std::lock_guard<std::mutex> lock(mutex_);
  return busy_ || job_.has_value() || !finished_.empty();
}

void PlannerWorker::submit(PlannerJob job)
{
  if (threading_ == WorkerThreading::InLine) {
    PlannerOutputs outputs = run(job);
    const std::lock_guard<std::mutex> lock(mutex_);
    finished_.push_back(std::move(outputs));
    return;
  }
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (job_ || busy_) {
      throw std::logic_error("planner worker: a job was handed over while the previous one is running");
    }
    job_ = std::move(job);
  }
  wake_.notify_one();
}

std::vector<PlannerOutputs> PlannerWorker::takeFinished()
{
  const std::lock_guard<std::mutex> lock(mutex_);
  std::vector<PlannerOutputs> finished;
  finished.swap(finished_);
  return finished;
}

void PlannerWorker::loop()
{
  std::unique_lock<std::mutex> lock(mutex_);
  while (true) {
    wake_.wait(lock, [this] { return stopping_ || job_.has_value(); });
    if (stopping_) {
      return;
    }
    PlannerJob job = std::move(*job_);
    job_.reset();
    busy_ = true;
    lock.unlock();
    PlannerOutputs outputs = run(job);
    lock.lock();
    busy_ = false;
    finished_.push_back(std::move(outputs));
  }
}

PlannerOutputs PlannerWorker::run(const PlannerJob& job)
{
  const PlannerJobResult finished = runPlannerJob(planner_, job);
  return toOutputs(planner_, finished, clock_(), true);
}

}  // namespace ifar::planner
