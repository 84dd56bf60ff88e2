#pragma once
// Background work below the UI thread (docs/architecture.md §4, "Priority"). On a 2-core machine
// the editor's frame (the UI thread and the software rasteriser's threads) shares the cores with
// the adaptive update, the latent map and training; without a priority, a drag started right
// after a release waits on them for a frame or two.

namespace mgp {

// Turns the policy on or off for the whole process (the editor turns it on; batch commands and
// tests leave it off, where background work is the work). Threads pick it up as their next job
// starts (lowerThisThreadIfBackground).
void setBackgroundWorkersYield(bool on);
bool backgroundWorkersYield();

// How far a yielding worker's nice value is raised above the thread that started it (capped at
// 19): at +10 the kernel gives it about a tenth of a core the UI thread wants (CFS weights 110
// against 1024).
constexpr int kBackgroundNice = 10;

// Called by a worker thread before each job: with the policy on, raises this thread's nice value by
// kBackgroundNice once (the threads a job starts inherit it). Returns whether this thread now runs
// lowered. A no-op returning false off Linux.
bool lowerThisThreadIfBackground();

// This thread's nice value (0 where unknown): for the test.
int thisThreadNice();

}  // namespace mgp
