// The rows of a frame (the arrays of io/frame.hpp) of the particles each rank of a decomposed run
// owns, joined on rank 0 into the whole frame (one .vtp, rank 0 then holding every particle's rows:
// the size limit of that output, docs/parallel.md); with output.pieces each rank writes its own
// (distributed/distributed_run.cpp). The wall points of output.walls likewise (JoinedWalls).
#pragma once
#include <cstdint>
#include <vector>

#include "io/frame.hpp"
#include "io/frame_storage.hpp"
#include "parallel/communicator.hpp"

namespace arksph::distributed {

// Collective. Every rank's rows joined on rank 0 in id order (parallel/join_by_id.hpp), the
// free_surface array with them where the ranks' frames carry it; the other ranks hold an empty frame.
class JoinedFrame {
 public:
  // `mine`: the rank's rows, read row by row during the join (a view of live fields).
  JoinedFrame(const parallel::Communicator& comm, const Frame& mine, std::size_t n);
  // The same from a copy of the rank's rows (so that the fields they view may be freed first).
  struct Copy {
    explicit Copy(const Frame& mine);
    Frame frame;
    std::vector<std::int64_t> id;
    std::vector<double> values;
  };
  JoinedFrame(const parallel::Communicator& comm, const Copy& mine, std::size_t n);
  const Frame& frame() const { return frame_; }

 private:
  template <class Row>
  void join(const parallel::Communicator& comm, const Frame& mine, Row&& row, std::size_t n);
  FrameStorage rows_;
  std::vector<std::uint8_t> free_surface_;
  Frame frame_;
};

// Collective. The wall points of every rank's particles (output.walls, run/wall_frame.hpp) joined
// on rank 0 in id order, the images of one particle in their rank's order: the rows one process
// writes. The other ranks hold an empty frame.
class JoinedWalls {
 public:
  JoinedWalls(const parallel::Communicator& comm, const Frame& mine);
  const Frame& frame() const { return frame_; }

 private:
  FrameStorage rows_;
  Frame frame_;
};

}  // namespace arksph::distributed
