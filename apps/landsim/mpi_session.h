#pragma once
// The MPI world this process runs in, if any. Under `mpirun` (or srun with PMI) landsim
// initialises MPI and renders with the other ranks; launched plainly it is a world of one
// and no MPI call is made. Built without MPI, it is always a world of one.
#include <string>

namespace landsim::app {

class MpiSession {
 public:
  MpiSession(int& argc, char**& argv);
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }
  bool distributed() const { return size_ > 1; }
  // Ranks on this machine (they share its memory).
  int ranks_on_node() const { return ranks_on_node_; }
  // "rank 3 of 8: ", or "" in a world of one: the prefix of logs and messages.
  std::string label() const;
  // Ends every rank's process (mpirun then fails the job) after a fatal error on this one.
  [[noreturn]] void abort(int code) const;

 private:
  int rank_ = 0;
  int size_ = 1;
  int ranks_on_node_ = 1;
  bool initialised_ = false;
};

// The session main() opened (nullptr before it exists).
const MpiSession* current_session();

}  // namespace landsim::app
