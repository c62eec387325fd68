#include "results/record_bytes.h"

#include <cstring>
#include <stdexcept>

#include <fmt/format.h>

namespace twb {

template <>
FilmFields blank_record<FilmFields>() {
  return FilmFields{1, false, FilmMesh(0.0, 1.0, 3, 8), {}, {}, {}, {}, {}, {}, {}};
}

void RecordWriter::operator()(const std::string& s) {
  count(s.size());
  bytes_.append(s);
}

void RecordWriter::operator()(const FilmMesh& m) {
  (*this)(m.inner_radius()), (*this)(m.outer_radius()), (*this)(m.radial_nodes()), (*this)(m.circumferential_nodes());
}

void RecordReader::operator()(bool& v) {
  std::uint8_t byte = 0;
  raw(&byte, sizeof byte);
  if (byte > 1) damaged();
  v = byte == 1;
}

void RecordReader::operator()(std::string& s) {
  const std::size_t n = count();
  s.assign(bytes_.data() + at_, n);
  at_ += n;
}

void RecordReader::operator()(FilmMesh& m) {
  double r_in = 0, r_out = 0;
  int nr = 0, nt = 0;
  (*this)(r_in), (*this)(r_out), (*this)(nr), (*this)(nt);
  m = FilmMesh(r_in, r_out, nr, nt);
}

std::size_t RecordReader::count() {
  std::uint64_t n = 0;
  (*this)(n);
  // Every value written takes a byte at least.
  if (n > bytes_.size() - at_) damaged();
  return std::size_t(n);
}

void RecordReader::finish() const {
  if (!done()) damaged();
}

void RecordReader::damaged() const { throw std::runtime_error(fmt::format("{} is damaged", what_)); }

void RecordReader::raw(void* p, std::size_t n) {
  if (n > bytes_.size() - at_) throw std::runtime_error(fmt::format("{} ends early", what_));
  std::memcpy(p, bytes_.data() + at_, n);
  at_ += n;
}

}  // namespace twb
