#pragma once
// rt-mpi's messages: what rank 0 sends every rank before the render (its command line, the scene
// file's text, the model files' bytes) packed into one byte string, and the collective steps
// every rank takes together (a broadcast of bytes, the first failure of any rank).

#include <mpi.h>

#include <cstdint>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace rt::mpi {

/// Bytes appended in order: 64-bit integers and length-prefixed strings.
class Packer {
 public:
  void u64(std::uint64_t v) { bytes_.append(reinterpret_cast<const char*>(&v), sizeof v); }
  void str(const std::string& s) {
    u64(s.size());
    bytes_ += s;
  }
  std::string& bytes() noexcept { return bytes_; }

 private:
  std::string bytes_;
};

/// Reads what a Packer wrote, in the same order. @throws std::runtime_error past the end.
class Unpacker {
 public:
  explicit Unpacker(const std::string& bytes) : bytes_(bytes) {}
  std::uint64_t u64() {
    need(sizeof(std::uint64_t));
    std::uint64_t v;
    std::memcpy(&v, bytes_.data() + at_, sizeof v);
    at_ += sizeof v;
    return v;
  }
  std::string str() {
    const std::uint64_t n = u64();
    need(n);
    std::string s = bytes_.substr(at_, n);
    at_ += n;
    return s;
  }

 private:
  void need(std::uint64_t n) const {
    if (n > bytes_.size() - at_)
      throw std::runtime_error("a message from rank 0 ends early (" +
                               std::to_string(bytes_.size()) + " bytes)");
  }
  const std::string& bytes_;
  std::size_t at_ = 0;
};

/// Broadcasts root's bytes to every rank (any size: sent in pieces of at most 1 GiB).
inline void broadcastBytes(std::string& bytes, int root, MPI_Comm comm) {
  std::uint64_t size = bytes.size();
  MPI_Bcast(&size, 1, MPI_UINT64_T, root, comm);
  bytes.resize(size);
  constexpr std::uint64_t kPiece = std::uint64_t{1} << 30;
  for (std::uint64_t at = 0; at < size; at += kPiece) {
    const int n = static_cast<int>(std::min(kPiece, size - at));
    MPI_Bcast(bytes.data() + at, n, MPI_BYTE, root, comm);
  }
}

/// This process's host name (MPI_Get_processor_name).
inline std::string hostName() {
  char name[MPI_MAX_PROCESSOR_NAME];
  int length = 0;
  MPI_Get_processor_name(name, &length);
  return std::string(name, static_cast<std::size_t>(length));
}

/// Every rank's string, gathered on root (in rank order; empty elsewhere).
inline std::vector<std::string> gatherStrings(const std::string& mine, int root, MPI_Comm comm) {
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  const int length = static_cast<int>(mine.size());
  std::vector<int> lengths(static_cast<std::size_t>(size)), offsets(static_cast<std::size_t>(size));
  MPI_Gather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, root, comm);
  std::string all;
  if (rank == root) {
    int total = 0;
    for (int r = 0; r < size; ++r) {
      offsets[static_cast<std::size_t>(r)] = total;
      total += lengths[static_cast<std::size_t>(r)];
    }
    all.resize(static_cast<std::size_t>(total));
  }
  MPI_Gatherv(mine.data(), length, MPI_CHAR, all.data(), lengths.data(), offsets.data(), MPI_CHAR,
              root, comm);
  std::vector<std::string> out;
  if (rank == root)
    for (int r = 0; r < size; ++r)
      out.push_back(all.substr(static_cast<std::size_t>(offsets[static_cast<std::size_t>(r)]),
                               static_cast<std::size_t>(lengths[static_cast<std::size_t>(r)])));
  return out;
}

/// A rank's failure: which rank, on which host, and why.
struct RankFailure {
  int rank = 0;
  std::string host;
  std::string message;
};

/// Collective: every rank says whether it failed (a non-empty error); every rank learns whether
/// any did, and rank 0 which one first (the lowest rank that failed, with its host).
inline std::optional<RankFailure> firstFailure(const std::string& error,
                                               const std::vector<std::string>& hosts,
                                               MPI_Comm comm) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  const std::vector<std::string> errors = gatherStrings(error, 0, comm);
  int failed = -1;
  for (std::size_t r = 0; r < errors.size(); ++r)
    if (!errors[r].empty()) {
      failed = static_cast<int>(r);
      break;
    }
  MPI_Bcast(&failed, 1, MPI_INT, 0, comm);
  if (failed < 0) return std::nullopt;
  if (rank != 0) return RankFailure{failed, "", ""};
  return RankFailure{failed, hosts[static_cast<std::size_t>(failed)],
                     errors[static_cast<std::size_t>(failed)]};
}

}  // namespace rt::mpi
