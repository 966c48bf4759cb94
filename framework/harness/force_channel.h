// The reference forces over a pipe: the checks of tasks 3 and 5 run the student's steppers with
// the reference force models (a6/force_model.h), which stay in the grader. The probe gets a
// ForceModel that asks the grader for each force on two extra fds; a grader thread answers.
//
// Design note: why not link the models into the probe. Student code can read whatever is in its
// address space: a probe holding the models hands a student tasks 1 and 2 solved. Over the pipe
// it sees the forces of the states it asks about, which a stepper gets anyway.
//
// The format (native byte order, both ends on one machine): a 4-byte count n (1 to
// kMaxRequestDoubles), then n doubles, the first the kind. The rest are the field lists of
// harness/wire_fields.h, the probe's requests' own, as doubles: a spring is fields(Spring), each
// of its particles as forceInputs(Particle) (x, v, m, T); a particle forceInputs(Particle); an
// environment fields(Environment), a list as its length and then its items. A field added to
// Spring or Environment (and listed there, which tests/grader/wire_test.cpp demands) reaches
// every reference force with no other edit.
//   1, spring                          -> its force (2 doubles)
//   2, particle, environment           -> its external force
//   3, count, count springs            -> their forces (2 count doubles)
//   4, count, environment, count particles -> their external forces
// The batches make a stepper cheap: all of a state's forces in one round trip
// (ForceModel::springAmong, externalAmong); a batch of externals whose count times (1 + its
// obstacles) passes kMaxRequestDoubles is the grader's work bound, so the probe asks those forces
// one at a time. A malformed request (a count that is no whole number, a list longer than what
// follows, a spring type that is none, more than kMaxObstacles obstacles, a batch past the work
// bound) ends the serving: the probe's next force fails, and only its own checks suffer.
#pragma once

#include <atomic>
#include <cstddef>

#include "a6/force_model.h"

namespace a6::harness::forcechannel {

/// The fds the probe asks on (it writes requests to the first, reads answers from the second).
constexpr int kRequestFd = 5;
constexpr int kAnswerFd = 6;

constexpr std::size_t kMaxObstacles = 1024;  ///< planes + circles of one environment
constexpr std::size_t kMaxRequestDoubles = std::size_t{1} << 21;  ///< 16 MiB

/// The probe's side: a ForceModel that asks over `requestFd` and `answerFd` (a force that cannot
/// be had, because the grader is gone or the environment is too large, is NaN).
ForceModel remoteModel(int requestFd = kRequestFd, int answerFd = kAnswerFd);

/// True when the grader gave this process the two fds (the probe of a release, or one started
/// by hand, has none: it then uses the student's own forces).
bool available(int requestFd = kRequestFd, int answerFd = kAnswerFd);

/// The grader's side: answers requests read from `requestFd` with `models` on `answerFd` until
/// the requests end, one is malformed, or `stopFd` becomes readable (or is closed). Never throws.
/// Returns how many were answered; `answered`, when given, counts them as they go (for the
/// grader's time allowance).
std::size_t serve(int requestFd, int answerFd, int stopFd, const ForceModel& models,
                  std::atomic<std::size_t>* answered = nullptr);

}  // namespace a6::harness::forcechannel
