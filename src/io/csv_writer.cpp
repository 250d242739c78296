// CSV time series and tables; atomic text writes.
#include "io/csv_writer.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <utility>

#include "core/errors.hpp"

namespace arksph {
namespace {

[[noreturn]] void fail(const std::string& path, int err) {
  throw OutputError("cannot write " + path + ": " + std::strerror(err));
}

// A header cell, quoted per RFC 4180 if it holds a comma, quote or line break.
std::string csv_cell(const std::string& s) {
  if (s.find_first_of(",\"\r\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += (c == '"') ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

std::string header_line(const std::vector<std::string>& columns) {
  std::string line;
  for (std::size_t i = 0; i < columns.size(); ++i) {
    if (i) line += ',';
    line += csv_cell(columns[i]);
  }
  return line + '\n';
}

std::string values_line(const std::vector<double>& values, std::size_t ncols, const std::string& path) {
  if (values.size() != ncols)
    throw std::invalid_argument(path + ": CSV row has " + std::to_string(values.size()) + " values for " +
                                std::to_string(ncols) + " columns");
  std::string line;
  char buf[32];
  for (std::size_t i = 0; i < values.size(); ++i) {
    std::snprintf(buf, sizeof buf, "%.10g", values[i]);
    if (i) line += ',';
    line += buf;
  }
  return line + '\n';
}

}  // namespace

std::string temporary_path(const std::string& path) { return path + ".tmp." + std::to_string(::getpid()); }

void write_text_atomic(const std::string& path, const std::string& text) {
  const std::string tmp = temporary_path(path);
  std::FILE* f = std::fopen(tmp.c_str(), "wb");
  if (!f) fail(path, errno);
  errno = 0;
  int err = 0;  // first error seen: short write, flush or close (a full disk may show only here)
  if (std::fwrite(text.data(), 1, text.size(), f) != text.size()) err = errno ? errno : EIO;
  if (std::fflush(f) != 0 && !err) err = errno;
  if (std::fclose(f) != 0 && !err) err = errno;
  if (err) {
    std::remove(tmp.c_str());
    fail(path, err);
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    err = errno;
    std::remove(tmp.c_str());
    fail(path, err);
  }
}

TimeseriesCsv::TimeseriesCsv(TimeseriesCsv&& o) noexcept
    : file_(std::exchange(o.file_, nullptr)), path_(std::move(o.path_)), columns_(std::move(o.columns_)) {}

TimeseriesCsv& TimeseriesCsv::operator=(TimeseriesCsv&& o) noexcept {
  if (this != &o) {
    close();
    file_ = std::exchange(o.file_, nullptr);
    path_ = std::move(o.path_);
    columns_ = std::move(o.columns_);
  }
  return *this;
}

void TimeseriesCsv::open(const std::string& path, std::vector<std::string> columns) {
  close();
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (!f) fail(path, errno);
  file_ = f;
  path_ = path;
  columns_ = std::move(columns);
  const std::string line = header_line(columns_);
  if (std::fputs(line.c_str(), file_) < 0 || std::fflush(file_) != 0) fail(path_, errno);
}

void TimeseriesCsv::row(const std::vector<double>& values) {
  if (!file_) throw std::logic_error("TimeseriesCsv::row: file not open");
  const std::string line = values_line(values, columns_.size(), path_);
  if (std::fputs(line.c_str(), file_) < 0 || std::fflush(file_) != 0) fail(path_, errno);
}

void TimeseriesCsv::close() {
  if (file_) std::fclose(file_);
  file_ = nullptr;
}

void write_csv(const std::string& path, const std::vector<std::string>& columns,
               const std::vector<std::vector<double>>& rows) {
  std::string text = header_line(columns);
  for (const auto& r : rows) text += values_line(r, columns.size(), path);
  write_text_atomic(path, text);
}

}  // namespace arksph
