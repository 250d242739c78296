// Plain-text output: the CSV time series (one flushed row per output time), small CSV tables, and
// the atomic text-file write (tmp + rename) shared by the PVD and JSON writers.
#pragma once
#include <cstdio>
#include <string>
#include <vector>

namespace arksph {

// The temporary a file is written to before it is renamed onto `path`: `path.tmp.PID`, unique per
// process, so that two processes writing the same file never share a temporary.
std::string temporary_path(const std::string& path);

// Writes `text` to temporary_path(path) and renames it onto `path`, so readers never see a partial
// file. Throws OutputError("cannot write <path>: <reason>") and removes the temporary on failure.
void write_text_atomic(const std::string& path, const std::string& text);

// A CSV file that grows by one row per call; each row is flushed, so a killed run keeps its rows.
class TimeseriesCsv {
 public:
  TimeseriesCsv() = default;
  TimeseriesCsv(const std::string& path, std::vector<std::string> columns) { open(path, std::move(columns)); }
  ~TimeseriesCsv() { close(); }
  TimeseriesCsv(const TimeseriesCsv&) = delete;
  TimeseriesCsv& operator=(const TimeseriesCsv&) = delete;
  TimeseriesCsv(TimeseriesCsv&& o) noexcept;
  TimeseriesCsv& operator=(TimeseriesCsv&& o) noexcept;

  // Creates (truncates) the file and writes the header line. Throws OutputError.
  void open(const std::string& path, std::vector<std::string> columns);
  // Appends one row, values with %.10g; values.size() must equal the number of columns
  // (std::invalid_argument otherwise). Throws OutputError on a write error.
  void row(const std::vector<double>& values);
  void close();

  bool is_open() const { return file_ != nullptr; }
  const std::vector<std::string>& columns() const { return columns_; }

 private:
  std::FILE* file_ = nullptr;
  std::string path_;
  std::vector<std::string> columns_;
};

// Writes a small table at once (header + rows, %.10g), atomically. Every row must have
// columns.size() values (std::invalid_argument otherwise).
void write_csv(const std::string& path, const std::vector<std::string>& columns,
               const std::vector<std::vector<double>>& rows);

}  // namespace arksph
