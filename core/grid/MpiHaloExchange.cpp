// MpiHaloExchange: the halo rules of HaloExchange.h over MPI ranks. The plan
// of a field kind (who sends which stored entries to whom, in which order) is
// built once with two all-to-all exchanges of indices; each call then moves
// only values, with non-blocking point-to-point messages.
#include "core/grid/MpiHaloExchange.h"

#include <mpi.h>

#include <algorithm>
#include <array>
#include <map>
#include <stdexcept>
#include <tuple>
#include <type_traits>

#include "core/grid/HaloIndex.h"
#include "core/grid/Loop.h"
#include "core/base/Mpi.h"

namespace tephra {

using halo::owner_index;
using halo::owner_patch;

// An entry of a local field: which field (index into the PatchFields) and its
// position in that field's data().
struct Entry {
  int field;
  long long offset;
};

struct MpiHaloExchange::Plan {
  // exchange(): per peer rank, the entries this rank sends (owned values) and
  // receives (ghosts), in the same order on both sides; same-rank copies.
  std::vector<std::vector<Entry>> send, recv;
  std::vector<std::pair<Entry, Entry>> local;  // (ghost to fill, owned source)
  // accumulate(): per home rank, this rank's stored copies sent there (the
  // sums come back in the same order); at the home, per slot the received
  // copies in (patch index, storage position) order, as positions in the
  // concatenated receive buffer, and the slot of every received copy.
  std::vector<std::vector<Entry>> copies;
  std::vector<int> recv_count;            // copies received from each rank
  std::vector<int> slot_begin, slot_terms;  // CSR: terms of slot s
  std::vector<int> slot_of;                 // per received copy
};

namespace {

constexpr int kTag = 4711;

template <class T>
constexpr int components() {
  if constexpr (std::is_same_v<T, double>) return 1;
  else return 3;
}
inline double* as_doubles(double& v) { return &v; }
inline double* as_doubles(Vec3& v) { return v.data(); }

// The (patch index, level index) requests of `asks` sent to the ranks that own
// them; returns, per peer rank, the requests that peer made of this rank.
// Each request is `width` ints.
std::vector<std::vector<int>> all_to_all_ints(const std::vector<std::vector<int>>& asks) {
  const int size = static_cast<int>(asks.size());
  std::vector<int> send_counts(size), recv_counts(size), sdispl(size, 0), rdispl(size, 0);
  for (int r = 0; r < size; ++r) send_counts[r] = static_cast<int>(asks[r].size());
  MPI_Alltoall(send_counts.data(), 1, MPI_INT, recv_counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
  for (int r = 1; r < size; ++r) {
    sdispl[r] = sdispl[r - 1] + send_counts[r - 1];
    rdispl[r] = rdispl[r - 1] + recv_counts[r - 1];
  }
  std::vector<int> sendbuf;
  for (const auto& a : asks) sendbuf.insert(sendbuf.end(), a.begin(), a.end());
  std::vector<int> recvbuf(rdispl.back() + recv_counts.back());
  MPI_Alltoallv(sendbuf.data(), send_counts.data(), sdispl.data(), MPI_INT, recvbuf.data(), recv_counts.data(),
                rdispl.data(), MPI_INT, MPI_COMM_WORLD);
  std::vector<std::vector<int>> got(size);
  for (int r = 0; r < size; ++r) got[r].assign(recvbuf.begin() + rdispl[r], recvbuf.begin() + rdispl[r] + recv_counts[r]);
  return got;
}

MpiHaloExchange::Traffic g_traffic;  // MpiHaloExchange::traffic()

// Posts the sends of send_buf[r] to each rank r and the receives of
// recv_buf[r] (already sized) from it; the message to this rank is a copy.
// The buffers must stay in place until the requests complete.
std::vector<MPI_Request> post_buffers(int rank, std::vector<std::vector<double>>& send_buf,
                                      std::vector<std::vector<double>>& recv_buf) {
  const int size = static_cast<int>(send_buf.size());
  ++g_traffic.calls;
  std::vector<MPI_Request> req;
  req.reserve(2 * size);
  for (int r = 0; r < size; ++r) {
    if (r == rank || recv_buf[r].empty()) continue;
    req.emplace_back();
    MPI_Irecv(recv_buf[r].data(), static_cast<int>(recv_buf[r].size()), MPI_DOUBLE, r, kTag, MPI_COMM_WORLD,
              &req.back());
  }
  for (int r = 0; r < size; ++r) {
    if (r == rank || send_buf[r].empty()) continue;
    ++g_traffic.messages;
    g_traffic.doubles += static_cast<long long>(send_buf[r].size());
    req.emplace_back();
    MPI_Isend(send_buf[r].data(), static_cast<int>(send_buf[r].size()), MPI_DOUBLE, r, kTag, MPI_COMM_WORLD,
              &req.back());
  }
  recv_buf[rank] = send_buf[rank];
  return req;
}

// post_buffers, then wait for every message.
void exchange_buffers(int rank, std::vector<std::vector<double>>& send_buf, std::vector<std::vector<double>>& recv_buf) {
  std::vector<MPI_Request> req = post_buffers(rank, send_buf, recv_buf);
  MPI_Waitall(static_cast<int>(req.size()), req.data(), MPI_STATUSES_IGNORE);
}

// One field of a batch as doubles: each held patch's data, the components
// per entry and the field's plan.
struct BatchField {
  std::vector<double*> data;  // per held patch
  int nc = 1;
  const MpiHaloExchange::Plan* plan = nullptr;
  double* at(const Entry& e) const { return data[size_t(e.field)] + e.offset * nc; }
};

static_assert(sizeof(Vec3) == 3 * sizeof(double), "a Vec3 field is read as 3 doubles per entry");

// The messages of a batch between begin_exchange and finish_exchange.
struct BatchInFlight {
  std::vector<BatchField> fields;
  std::vector<std::vector<double>> sendb, recvb;
  std::vector<MPI_Request> req;
};

}  // namespace

MpiHaloExchange::Traffic MpiHaloExchange::traffic() { return g_traffic; }

MpiHaloExchange::MpiHaloExchange(const Grid& grid, std::vector<int> owner) : grid_(&grid), owner_(std::move(owner)) {
  if (owner_.size() != grid.patches.size())
    throw std::invalid_argument("MpiHaloExchange: one owner rank per patch expected");
  ensure_mpi_initialized();  // also with one rank: the calls below are MPI's
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  for (size_t p = 0; p < owner_.size(); ++p) {
    if (owner_[p] < 0 || owner_[p] >= size_)
      throw std::invalid_argument("MpiHaloExchange: patch " + std::to_string(p) + " owned by rank " +
                                  std::to_string(owner_[p]) + " of " + std::to_string(size_));
    if (owner_[p] == rank_) own_.push_back(int(p));
  }
}

MpiHaloExchange::~MpiHaloExchange() = default;

const MpiHaloExchange::Plan& MpiHaloExchange::plan(bool nodes, bool accumulate, int ghosts,
                                                   const std::vector<int>& fields_patches) {
  std::vector<int> key{nodes, accumulate, ghosts};
  key.insert(key.end(), fields_patches.begin(), fields_patches.end());
  auto it = plans_.find(key);
  if (it != plans_.end()) return *it->second;

  const Grid& g = *grid_;
  auto plan = std::make_unique<Plan>();
  Plan& P = *plan;
  // Field index of each patch held here (-1 if not held), and the field
  // shapes, built the way the PatchFields holds them.
  std::vector<int> field_of(g.patches.size(), -1);
  for (size_t n = 0; n < fields_patches.size(); ++n) {
    const int p = fields_patches[n];
    if (owner_[size_t(p)] != rank_)
      throw std::logic_error("MpiHaloExchange: the fields hold patch " + std::to_string(p) + " of rank " +
                             std::to_string(owner_[size_t(p)]));
    field_of[size_t(p)] = int(n);
  }
  auto make_shape = [&](int p) -> GridArray<char> {
    const Patch& pa = g.patches[size_t(p)];
    if (nodes)
      return GridArray<char>(pa.id, {pa.lo, pa.hi + IntVec3::Ones()}, {pa.extra_lo, pa.extra_hi + IntVec3::Ones()},
                             ghosts);
    return GridArray<char>(pa.id, pa.cells(), pa.cells_with_extra(), ghosts);
  };
  std::vector<GridArray<char>> shape;
  for (int p : fields_patches) shape.push_back(make_shape(p));

  if (!accumulate) {
    // Ghost entries of each held field, asked of the owning patch's rank.
    P.send.assign(size_, {});
    P.recv.assign(size_, {});
    std::vector<std::vector<int>> asks(size_);
    for (size_t n = 0; n < shape.size(); ++n) {
      const GridArray<char>& f = shape[n];
      const IndexRange own = f.with_extra();
      for_each_cell_serial(f.with_ghosts(), [&](int i, int j, int k) {
        const IntVec3 c(i, j, k);
        if (own.contains(c)) return;
        IntVec3 s;
        if (!owner_index(g, c, nodes, s)) return;
        const int q = owner_patch(g, s);
        const Entry ghost{int(n), (long long)f.offset(i, j, k)};
        if (owner_[size_t(q)] == rank_) {
          const int m = field_of[size_t(q)];
          P.local.push_back({ghost, Entry{m, (long long)shape[size_t(m)].offset(s[0], s[1], s[2])}});
        } else {
          P.recv[owner_[size_t(q)]].push_back(ghost);
          asks[owner_[size_t(q)]].insert(asks[owner_[size_t(q)]].end(), {q, s[0], s[1], s[2]});
        }
      });
    }
    const std::vector<std::vector<int>> wanted = all_to_all_ints(asks);
    for (int r = 0; r < size_; ++r)
      for (size_t a = 0; a + 3 < wanted[r].size(); a += 4) {
        const int q = wanted[r][a];
        const int m = field_of[size_t(q)];
        if (m < 0)
          throw std::logic_error("MpiHaloExchange: rank " + std::to_string(r) + " asked for patch " +
                                 std::to_string(q) + " which this rank's fields do not hold");
        P.send[r].push_back(Entry{m, (long long)shape[size_t(m)].offset(wanted[r][a + 1], wanted[r][a + 2],
                                                                         wanted[r][a + 3])});
      }
  } else {
    // Every stored copy of a physical node goes to the node's home rank with
    // its (patch index, position) so the home can add in the serial order.
    P.copies.assign(size_, {});
    std::vector<std::vector<int>> tell(size_);
    for (size_t n = 0; n < shape.size(); ++n) {
      const GridArray<char>& f = shape[n];
      const int p = fields_patches[n];
      for_each_cell_serial(f.with_ghosts(), [&](int i, int j, int k) {
        IntVec3 s;
        if (!owner_index(g, IntVec3(i, j, k), true, s)) return;
        const int home = owner_[size_t(owner_patch(g, s))];
        const long long off = (long long)f.offset(i, j, k);
        P.copies[home].push_back(Entry{int(n), off});
        tell[home].insert(tell[home].end(), {s[0], s[1], s[2], p, int(off)});
      });
    }
    const std::vector<std::vector<int>> got = all_to_all_ints(tell);
    // Received copies, numbered in rank order; grouped by slot and sorted.
    std::map<std::array<int, 3>, std::vector<std::tuple<int, int, int>>> by_slot;  // (patch, pos, g)
    P.recv_count.assign(size_, 0);
    int gidx = 0;
    for (int r = 0; r < size_; ++r) {
      P.recv_count[r] = int(got[r].size() / 5);
      for (size_t a = 0; a + 4 < got[r].size(); a += 5, ++gidx)
        by_slot[{got[r][a], got[r][a + 1], got[r][a + 2]}].emplace_back(got[r][a + 3], got[r][a + 4], gidx);
    }
    P.slot_of.assign(gidx, -1);
    P.slot_begin.push_back(0);
    int slot = 0;
    for (auto& [s, terms] : by_slot) {
      std::sort(terms.begin(), terms.end());
      for (const auto& t : terms) {
        P.slot_terms.push_back(std::get<2>(t));
        P.slot_of[size_t(std::get<2>(t))] = slot;
      }
      P.slot_begin.push_back(int(P.slot_terms.size()));
      ++slot;
    }
  }
  return *(plans_[key] = std::move(plan));
}

template <class FieldT>
void MpiHaloExchange::exchange_impl(PatchFields<FieldT>& pf, bool nodes) {
  using T = typename FieldT::value_type;
  constexpr int nc = components<T>();
  std::vector<int> patches(pf.size());
  for (size_t n = 0; n < pf.size(); ++n) patches[n] = pf.patch_index(n);
  const Plan& P = plan(nodes, false, pf.ghost_width(), patches);
  auto at = [&](const Entry& e) -> T& { return pf[size_t(e.field)].data()[e.offset]; };
  std::vector<std::vector<double>> sendb(size_), recvb(size_);
  for (int r = 0; r < size_; ++r) {
    sendb[r].reserve(P.send[r].size() * nc);
    for (const Entry& e : P.send[r]) {
      const double* v = as_doubles(at(e));
      sendb[r].insert(sendb[r].end(), v, v + nc);
    }
    recvb[r].resize(P.recv[r].size() * nc);
  }
  // Same-rank copies first, then the messages (overlapping them with
  // interior work is the next step of the issue 7 plan, docs/parallel.md).
  for (const auto& [ghost, src] : P.local) at(ghost) = at(src);
  exchange_buffers(rank_, sendb, recvb);
  for (int r = 0; r < size_; ++r)
    for (size_t k = 0; k < P.recv[r].size(); ++k) {
      double* v = as_doubles(at(P.recv[r][k]));
      for (int c = 0; c < nc; ++c) v[c] = recvb[r][k * nc + c];
    }
}

template <class T>
void MpiHaloExchange::accumulate_impl(PatchFields<NodeField<T>>& pf) {
  constexpr int nc = components<T>();
  std::vector<int> patches(pf.size());
  for (size_t n = 0; n < pf.size(); ++n) patches[n] = pf.patch_index(n);
  const Plan& P = plan(true, true, pf.ghost_width(), patches);
  auto at = [&](const Entry& e) -> T& { return pf[size_t(e.field)].data()[e.offset]; };
  // 1. Every copy to its home rank.
  std::vector<std::vector<double>> sendb(size_), recvb(size_);
  for (int r = 0; r < size_; ++r) {
    for (const Entry& e : P.copies[r]) {
      const double* v = as_doubles(at(e));
      sendb[r].insert(sendb[r].end(), v, v + nc);
    }
    recvb[r].resize(size_t(P.recv_count[r]) * nc);
  }
  exchange_buffers(rank_, sendb, recvb);
  // 2. At the home: the sums, in the serial order, from 0.
  std::vector<double> flat;
  for (const auto& b : recvb) flat.insert(flat.end(), b.begin(), b.end());
  const size_t nslots = P.slot_begin.size() - 1;
  std::vector<double> sum(nslots * nc, 0.0);
  for (size_t s = 0; s < nslots; ++s)
    for (int t = P.slot_begin[s]; t < P.slot_begin[s + 1]; ++t)
      for (int c = 0; c < nc; ++c) sum[s * nc + c] += flat[size_t(P.slot_terms[size_t(t)]) * nc + c];
  // 3. Each copy's slot sum back to where it came from (same order).
  size_t g = 0;
  for (int r = 0; r < size_; ++r)
    for (int k = 0; k < P.recv_count[r]; ++k, ++g)
      for (int c = 0; c < nc; ++c) recvb[r][size_t(k) * nc + c] = sum[size_t(P.slot_of[g]) * nc + c];
  for (int r = 0; r < size_; ++r) sendb[r].resize(P.copies[r].size() * nc);
  exchange_buffers(rank_, recvb, sendb);
  for (int r = 0; r < size_; ++r)
    for (size_t k = 0; k < P.copies[r].size(); ++k) {
      double* v = as_doubles(at(P.copies[r][k]));
      for (int c = 0; c < nc; ++c) v[c] = sendb[r][k * nc + c];
    }
}

void MpiHaloExchange::begin_exchange(CellHaloBatch& b) {
  auto fly = std::make_shared<BatchInFlight>();
  auto add = [&](auto& pf, int nc) {
    std::vector<int> patches(pf.size());
    BatchField bf;
    bf.nc = nc;
    for (size_t n = 0; n < pf.size(); ++n) {
      patches[n] = pf.patch_index(n);
      bf.data.push_back(as_doubles(pf[n].data()[0]));
    }
    bf.plan = &plan(false, false, pf.ghost_width(), patches);
    fly->fields.push_back(std::move(bf));
  };
  for (auto* f : b.scalars) add(*f, 1);
  for (auto* f : b.vectors) add(*f, 3);
  // Per peer: the fields' owned values in batch order, each in its plan's order.
  fly->sendb.assign(size_, {});
  fly->recvb.assign(size_, {});
  for (int r = 0; r < size_; ++r) {
    std::size_t n_recv = 0;
    for (const BatchField& f : fly->fields) {
      for (const Entry& e : f.plan->send[r]) fly->sendb[r].insert(fly->sendb[r].end(), f.at(e), f.at(e) + f.nc);
      n_recv += f.plan->recv[r].size() * f.nc;
    }
    fly->recvb[r].resize(n_recv);
  }
  // Same-rank copies now (their sources are the values at begin).
  for (const BatchField& f : fly->fields)
    for (const auto& [ghost, src] : f.plan->local) std::copy(f.at(src), f.at(src) + f.nc, f.at(ghost));
  fly->req = post_buffers(rank_, fly->sendb, fly->recvb);
  b.in_flight = std::move(fly);
}

void MpiHaloExchange::finish_exchange(CellHaloBatch& b) {
  auto fly = std::static_pointer_cast<BatchInFlight>(b.in_flight);
  if (!fly) throw std::logic_error("MpiHaloExchange::finish_exchange without begin_exchange");
  MPI_Waitall(static_cast<int>(fly->req.size()), fly->req.data(), MPI_STATUSES_IGNORE);
  for (int r = 0; r < size_; ++r) {
    const double* v = fly->recvb[size_t(r)].data();
    for (const BatchField& f : fly->fields)
      for (const Entry& e : f.plan->recv[r]) {
        std::copy(v, v + f.nc, f.at(e));
        v += f.nc;
      }
  }
  b.in_flight.reset();
}

void MpiHaloExchange::exchange(PatchFields<CellField<double>>& f) { exchange_impl(f, false); }
void MpiHaloExchange::exchange(PatchFields<CellField<Vec3>>& f) { exchange_impl(f, false); }
void MpiHaloExchange::exchange(PatchFields<NodeField<double>>& f) { exchange_impl(f, true); }
void MpiHaloExchange::exchange(PatchFields<NodeField<Vec3>>& f) { exchange_impl(f, true); }
void MpiHaloExchange::accumulate(PatchFields<NodeField<double>>& f) { accumulate_impl(f); }
void MpiHaloExchange::accumulate(PatchFields<NodeField<Vec3>>& f) { accumulate_impl(f); }

}  // namespace tephra
