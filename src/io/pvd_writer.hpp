// The ParaView time collection (.pvd) of the VTP frames. VTK has no writer for it, so the
// Collection XML is written by hand; it is rewritten atomically after every frame, so the file
// is valid (and lists every frame written so far) even if the run dies.
#pragma once
#include <string>
#include <utility>
#include <vector>

namespace arksph {

class PvdCollection {
 public:
  // The collection lives at dir/name; frame file names are relative to dir. Nothing is written
  // until the first add().
  explicit PvdCollection(std::string dir, std::string name = "particles.pvd");

  // An id written as the comment <!-- arksph run_id="ID" --> after the XML declaration ("" : none).
  void set_run_id(std::string id) { run_id_ = std::move(id); }

  // Appends a frame and rewrites the collection. Throws OutputError("cannot write ...").
  void add(double time, const std::string& vtp_filename);

  // Rewrites the collection as it stands (also valid with no frame).
  void write() const;

  const std::string& path() const { return path_; }
  std::size_t size() const { return frames_.size(); }

 private:
  struct Entry {
    double time;
    std::string file;
  };
  std::string path_;
  std::string run_id_;
  std::vector<Entry> frames_;
};

}  // namespace arksph
