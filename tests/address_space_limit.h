#pragma once
// A test's own address-space limit (`ulimit -v`): the soft RLIMIT_AS lowered to what this
// process has mapped now plus `room` bytes, and put back when the object goes out of scope, so an
// assertion that ends the test early does not leave the rest of the suite starved. Not for a
// sanitized build, whose reserved shadow memory such a limit would starve (tests/test_size.h).

#include <sys/resource.h>
#include <unistd.h>

#include <fstream>

namespace agv::test {

class AddressSpaceLimit {
 public:
  explicit AddressSpaceLimit(double room) {
    std::ifstream statm("/proc/self/statm");
    double pages = 0.0;
    if (!(statm >> pages) || ::getrlimit(RLIMIT_AS, &saved_) != 0) {
      failed_ = true;
      return;
    }
    const double mapped = pages * static_cast<double>(::sysconf(_SC_PAGE_SIZE));
    struct rlimit low = saved_;
    low.rlim_cur = static_cast<rlim_t>(mapped + room);
    // A limit tighter already is left as it is: active() says the test has nothing to prove.
    if (saved_.rlim_cur != RLIM_INFINITY && saved_.rlim_cur <= low.rlim_cur) return;
    active_ = ::setrlimit(RLIMIT_AS, &low) == 0;
    failed_ = !active_;
  }
  ~AddressSpaceLimit() {
    if (active_) ::setrlimit(RLIMIT_AS, &saved_);
  }
  AddressSpaceLimit(const AddressSpaceLimit&) = delete;
  AddressSpaceLimit& operator=(const AddressSpaceLimit&) = delete;

  bool active() const { return active_; }
  // /proc/self/statm or the limit could not be read, or the limit not set: a broken test set-up.
  bool failed() const { return failed_; }

 private:
  struct rlimit saved_ {};
  bool active_ = false;
  bool failed_ = false;
};

}  // namespace agv::test
