/// @file MortarPass.cpp
/// @brief Nodal mortar quantities from the segment kernels (see the header).
///
/// Cross-rank summation (sumToOwners):
///  1. owner of every slave node: each rank marks its owned slave nodes
///     (ContactInterface::ownedSlaveNodes()) with its rank, -1 elsewhere; one
///     Teuchos::reduceAll(MAX) over the slave-node vector gives every rank the
///     full owner table (O(slave nodes), replicated like the interface itself);
///  2. every local entry is packed into a flat buffer of doubles for its owner
///     (global node numbers are stored as doubles: exact below 2^53);
///  3. exchangeByRank (core/Parallel.hpp: MPI_Alltoall of the sizes, MPI_Alltoallv of the buffers);
///  4. the owner unpacks the buffers in rank order (its own included) and adds
///     entries with the same node (NodalMortarEntry::add), so the summation order
///     is fixed for a given rank count.
/// Packed entry: node, D, gap, #M, (l, M_jl)..., dD row, dGap row, #dM,
/// (l, dM row)...; a row is #entries, (node, component, value)....
#include "coulomb/contact/interface/MortarPass.hpp"


#include <Teuchos_CommHelpers.hpp>
#include <algorithm>

#include "coulomb/contact/mortar/MortarSegment2D.hpp"
#include "coulomb/contact/mortar/MortarSegmentCurved2D.hpp"
#include "coulomb/contact/mortar/MortarSegment3D.hpp"
#include "coulomb/contact/mortar/MortarSegmentQuadratic3D.hpp"
#include "coulomb/contact/mortar/OverlapBound.hpp"
#include "coulomb/core/Error.hpp"
#include "coulomb/core/Parallel.hpp"

namespace coulomb::contact {

// ------------------------------------------------------------------ entries

namespace {

void addRow(DerivativeRow& to, const DerivativeRow& from) {
  for (const auto& [key, value] : from) to[key] += value;
}

}  // namespace

void NodalMortarEntry::add(const NodalMortarEntry& other) {
  COULOMB_CHECK(node == other.node, "adding mortar entries of different nodes");
  D += other.D;
  gap += other.gap;
  for (const auto& [l, value] : other.M) M[l] += value;
  addRow(dD, other.dD);
  addRow(dGap, other.dGap);
  for (const auto& [l, row] : other.dM) addRow(dM[l], row);
}

const NodalMortarEntry* NodalMortarQuantities::find(long long node) const {
  const auto it = std::lower_bound(entries.begin(), entries.end(), node,
                                   [](const NodalMortarEntry& e, long long n) { return e.node < n; });
  return it != entries.end() && it->node == node ? &*it : nullptr;
}

// --------------------------------------------------------------------- pass

namespace {

using mesh::FaceType;

/// The column of each kernel input of one pair, in the kernels' order
/// (slave coordinates, slave normals, master coordinates): a DoF (node,
/// component) of a face node, or for a normal component the key (node,
/// kNormalKey + k). That key stands for n_k of the slave node while a pass
/// sums its pairs: d q / d n_a is summed over every pair of node a first and
/// chained through d n_a / d x (some tens of DoFs of the faces around a)
/// once per row at the end of the pass (expandNormalKeys), not once per
/// pair — a node is in some tens of pairs.
constexpr int kNormalKey = 8;

std::vector<DofKey> inputKeys(int dim, const ContactFace& slave, const ContactFace& master) {
  const int nS = slave.numNodes, nM = master.numNodes;
  std::vector<DofKey> keys(static_cast<std::size_t>(dim * (2 * nS + nM)));
  for (int a = 0; a < nS; ++a)
    for (int c = 0; c < dim; ++c) {
      keys[a * dim + c] = {slave.nodes[a], c};
      keys[dim * nS + a * dim + c] = {slave.nodes[a], kNormalKey + c};
    }
  for (int l = 0; l < nM; ++l)
    for (int c = 0; c < dim; ++c) keys[dim * 2 * nS + l * dim + c] = {master.nodes[l], c};
  return keys;
}

template <std::size_t N>
void addToRow(const std::array<double, N>& dq, const std::vector<DofKey>& keys, DerivativeRow& row) {
  for (std::size_t i = 0; i < N; ++i)
    if (dq[i] != 0.0) row[keys[i]] += dq[i];
}

/// Adds the values (and derivatives, if `lin`) of one pair to the nodal entries.
/// Value: a MortarSegment2D<double> or MortarSegment3D<S, M, double>; Lin: the
/// matching linearization (or nullptr).
template <typename Value, typename Lin>
void accumulate(const Value& value, const Lin* lin, const std::vector<DofKey>* keys, const ContactFace& slave,
                const ContactFace& master, std::map<long long, NodalMortarEntry>& out) {
  const int nS = slave.numNodes, nM = master.numNodes;
  for (int j = 0; j < nS; ++j) {
    NodalMortarEntry& e = out[slave.nodes[j]];
    e.node = slave.nodes[j];
    e.D += value.D[j];
    e.gap += value.gap[j];
    for (int l = 0; l < nM; ++l) e.M[master.nodes[l]] += value.M[j][l];
    if (lin) {
      addToRow(lin->dD[j], *keys, e.dD);
      addToRow(lin->dGap[j], *keys, e.dGap);
      for (int l = 0; l < nM; ++l) addToRow(lin->dM[j][l], *keys, e.dM[master.nodes[l]]);
    }
  }
}

template <FaceType F>
FaceNodes<F, double> faceCoordinates(const ContactFace& f, const InterfaceConfiguration& x) {
  FaceNodes<F, double> out{};
  for (int a = 0; a < FaceTraits<F>::nodes; ++a)
    for (int c = 0; c < FaceTraits<F>::spaceDim; ++c) out[a][c] = x.point(f.interfaceIndex[a])[c];
  return out;
}

template <FaceType F>
FaceNodes<F, double> faceNormals(const ContactFace& f, const ContactInterface& contact,
                                 const std::vector<NodalNormal>& normals) {
  FaceNodes<F, double> out{};
  for (int a = 0; a < FaceTraits<F>::nodes; ++a) {
    const int i = contact.slaveNodeIndex(f.nodes[a]);
    COULOMB_CHECK(i >= 0, "slave face node is no slave node");
    for (int c = 0; c < FaceTraits<F>::spaceDim; ++c) out[a][c] = normals[i].n[c];
  }
  return out;
}

struct PairContext {
  const ContactInterface& contact;
  const InterfaceConfiguration& x;
  const std::vector<NodalNormal>& normals;
  bool withDerivatives;
  double tolerance;
  std::map<long long, NodalMortarEntry>& out;
};

/// One pair with the segment kernel `integrate(xs, ns, xm)` (doubles) and
/// its `linearize(xs, ns, xm)` (values and derivatives). Most candidate
/// pairs of a search do not overlap: the plain doubles find out before the
/// derivatives are paid for (Sacado, 8-80 times the work).
template <FaceType S, FaceType Mf, class Integrate, class Linearize>
void integrateWith(const PairContext& p, const ContactFace& s, const ContactFace& m, Integrate&& integrate,
                   Linearize&& linearize) {
  const auto xs = faceCoordinates<S>(s, p.x);
  const auto ns = faceNormals<S>(s, p.contact, p.normals);
  const auto xm = faceCoordinates<Mf>(m, p.x);
  if (!projectionsMayOverlap<S, Mf>(xs, xm)) return;  // most candidates: no clipping (OverlapBound.hpp)
  using Lin = decltype(linearize(xs, ns, xm));
  if (p.withDerivatives && integrate(xs, ns, xm).contributes) {
    const Lin lin = linearize(xs, ns, xm);
    if (!lin.value.contributes) return;
    const std::vector<DofKey> keys = inputKeys(FaceTraits<S>::spaceDim, s, m);
    accumulate(lin.value, &lin, &keys, s, m, p.out);
  } else if (!p.withDerivatives) {
    const auto value = integrate(xs, ns, xm);
    if (!value.contributes) return;
    accumulate(value, static_cast<const Lin*>(nullptr), nullptr, s, m, p.out);
  }
}

/// A 2D pair: the closed-form Line2 kernel, or the general one when a face
/// is a quadratic Line3 (MortarSegmentCurved2D.hpp).
template <FaceType S, FaceType Mf>
void pair2D(const PairContext& p, const ContactFace& s, const ContactFace& m) {
  const bool ring = p.contact.axisymmetric();
  if constexpr (S == FaceType::Line2 && Mf == FaceType::Line2)
    integrateWith<S, Mf>(
        p, s, m, [&](const auto& xs, const auto& ns, const auto& xm) { return integrateSegment2D<double>(xs, ns, xm, p.tolerance, ring); },
        [&](const auto& xs, const auto& ns, const auto& xm) { return linearizeSegment2D(xs, ns, xm, p.tolerance, ring); });
  else
    integrateWith<S, Mf>(
        p, s, m,
        [&](const auto& xs, const auto& ns, const auto& xm) {
          return integrateCurvedSegment2D<S, Mf, double>(xs, ns, xm, p.tolerance, ring);
        },
        [&](const auto& xs, const auto& ns, const auto& xm) {
          return linearizeCurvedSegment2D<S, Mf>(xs, ns, xm, p.tolerance, ring);
        });
}

/// A 3D pair: the linear kernel, or the sub-facet one when a face is
/// quadratic (MortarSegmentQuadratic3D.hpp; any quadratic type with any other).
template <FaceType S, FaceType Mf>
void pair3D(const PairContext& p, const ContactFace& s, const ContactFace& m) {
  constexpr bool quadratic = S == FaceType::Quad9 || Mf == FaceType::Quad9 || transformedSlaveBasis(S) ||
                             transformedSlaveBasis(Mf);
  if constexpr (quadratic)
    integrateWith<S, Mf>(
        p, s, m,
        [&](const auto& xs, const auto& ns, const auto& xm) {
          return integrateQuadraticSegment3D<S, Mf, double>(xs, ns, xm, p.tolerance);
        },
        [&](const auto& xs, const auto& ns, const auto& xm) {
          return linearizeQuadraticSegment3D<S, Mf>(xs, ns, xm, p.tolerance);
        });
  else
    integrateWith<S, Mf>(
        p, s, m,
        [&](const auto& xs, const auto& ns, const auto& xm) {
          return integrateSegment3D<S, Mf, double>(xs, ns, xm, p.tolerance);
        },
        [&](const auto& xs, const auto& ns, const auto& xm) { return linearizeSegment3D<S, Mf>(xs, ns, xm, p.tolerance); });
}

void integratePair(const PairContext& p, const ContactFace& s, const ContactFace& m) {
  using F = FaceType;
  if (p.contact.dimension() == 2) {
    const bool sLine3 = s.type == F::Line3, mLine3 = m.type == F::Line3;
    if (sLine3) return mLine3 ? pair2D<F::Line3, F::Line3>(p, s, m) : pair2D<F::Line3, F::Line2>(p, s, m);
    return mLine3 ? pair2D<F::Line2, F::Line3>(p, s, m) : pair2D<F::Line2, F::Line2>(p, s, m);
  }
  // 3D: Tri3, Quad4, Tri6, Quad8 or Quad9 on either side (pair3D picks the kernel).
  auto withMaster = [&](auto slave) {
    constexpr F S = decltype(slave)::value;
    switch (m.type) {
      case F::Tri3: return pair3D<S, F::Tri3>(p, s, m);
      case F::Quad9: return pair3D<S, F::Quad9>(p, s, m);
      case F::Quad8: return pair3D<S, F::Quad8>(p, s, m);
      case F::Tri6: return pair3D<S, F::Tri6>(p, s, m);
      default: return pair3D<S, F::Quad4>(p, s, m);
    }
  };
  switch (s.type) {
    case F::Tri3: return withMaster(std::integral_constant<F, F::Tri3>{});
    case F::Quad9: return withMaster(std::integral_constant<F, F::Quad9>{});
    case F::Quad8: return withMaster(std::integral_constant<F, F::Quad8>{});
    case F::Tri6: return withMaster(std::integral_constant<F, F::Tri6>{});
    default: return withMaster(std::integral_constant<F, F::Quad4>{});
  }
}

/// Replaces the normal keys of `row` (kNormalKey) by their chain through
/// the nodal normals' derivatives: d q / d x += sum_k (d q / d n_a,k) d n_a,k / d x.
void expandNormalKeys(DerivativeRow& row, const ContactInterface& contact, const std::vector<NodalNormal>& normals) {
  std::vector<std::pair<DofKey, double>> normalTerms;
  for (auto it = row.begin(); it != row.end();) {
    if (it->first.second < kNormalKey) {
      ++it;
      continue;
    }
    normalTerms.push_back(*it);
    it = row.erase(it);
  }
  for (const auto& [key, value] : normalTerms) {
    const int i = contact.slaveNodeIndex(key.first);
    COULOMB_CHECK(i >= 0 && !normals[i].derivative.empty(),
                  "mortar pass needs the normal derivative at node " + std::to_string(key.first + 1));
    const int k = key.second - kNormalKey;
    for (const NormalDerivative& d : normals[i].derivative) row[{d.node, d.component}] += value * d.dn[k];
  }
}

}  // namespace

NodalMortarQuantities integrateMortarPass(const ContactInterface& contact, const InterfaceConfiguration& x,
                                          const std::vector<NodalNormal>& normals, const SearchResult& pairs,
                                          bool withDerivatives, double relativeTolerance) {
  COULOMB_CHECK(normals.size() == contact.slaveNodes().size(),
                  "mortar pass needs one nodal normal per slave node");
  COULOMB_CHECK(x.dimension == contact.dimension(), "configuration dimension mismatch");
  std::map<long long, NodalMortarEntry> out;
  const PairContext context{contact, x, normals, withDerivatives, relativeTolerance, out};
  for (std::size_t k = 0; k < pairs.slaveFaces.size(); ++k) {
    const ContactFace& s = contact.slaveFaces()[pairs.slaveFaces[k]];
    for (int m : pairs.candidates[k]) integratePair(context, s, contact.masterFaces()[m]);
  }
  NodalMortarQuantities result;
  result.dimension = contact.dimension();
  result.withDerivatives = withDerivatives;
  result.entries.reserve(out.size());
  for (auto& [node, entry] : out) {
    if (withDerivatives) {
      expandNormalKeys(entry.dD, contact, normals);
      expandNormalKeys(entry.dGap, contact, normals);
      for (auto& [l, row] : entry.dM) expandNormalKeys(row, contact, normals);
    }
    result.entries.push_back(std::move(entry));
  }
  return result;
}

// ------------------------------------------------------------ summation

namespace {

void packRow(std::vector<double>& b, const DerivativeRow& row) {
  b.push_back(static_cast<double>(row.size()));
  for (const auto& [key, value] : row) {
    b.push_back(static_cast<double>(key.first));
    b.push_back(key.second);
    b.push_back(value);
  }
}

void pack(std::vector<double>& b, const NodalMortarEntry& e) {
  b.push_back(static_cast<double>(e.node));
  b.push_back(e.D);
  b.push_back(e.gap);
  b.push_back(static_cast<double>(e.M.size()));
  for (const auto& [l, value] : e.M) {
    b.push_back(static_cast<double>(l));
    b.push_back(value);
  }
  packRow(b, e.dD);
  packRow(b, e.dGap);
  b.push_back(static_cast<double>(e.dM.size()));
  for (const auto& [l, row] : e.dM) {
    b.push_back(static_cast<double>(l));
    packRow(b, row);
  }
}

struct Reader {
  const double* p;
  long long nextInt() { return static_cast<long long>(*p++); }
  double next() { return *p++; }
};

DerivativeRow unpackRow(Reader& r) {
  DerivativeRow row;
  const long long n = r.nextInt();
  for (long long i = 0; i < n; ++i) {
    const long long node = r.nextInt();
    const int component = static_cast<int>(r.nextInt());
    row.emplace_hint(row.end(), DofKey{node, component}, r.next());
  }
  return row;
}

NodalMortarEntry unpack(Reader& r) {
  NodalMortarEntry e;
  e.node = r.nextInt();
  e.D = r.next();
  e.gap = r.next();
  const long long nM = r.nextInt();
  for (long long i = 0; i < nM; ++i) {
    const long long l = r.nextInt();
    e.M.emplace_hint(e.M.end(), l, r.next());
  }
  e.dD = unpackRow(r);
  e.dGap = unpackRow(r);
  const long long ndM = r.nextInt();
  for (long long i = 0; i < ndM; ++i) {
    const long long l = r.nextInt();
    e.dM.emplace_hint(e.dM.end(), l, unpackRow(r));
  }
  return e;
}

}  // namespace

NodalMortarQuantities sumToOwners(const ContactInterface& contact, const NodalMortarQuantities& local) {
  const Teuchos::Comm<int>& comm = *contact.comm();
  const int size = comm.getSize(), rank = comm.getRank();
  NodalMortarQuantities result;
  result.dimension = local.dimension;
  result.withDerivatives = local.withDerivatives;

  // 1. owner table of the slave nodes
  const std::size_t numSlave = contact.slaveNodes().size();
  std::vector<int> mine(numSlave, -1), owner(numSlave, -1);
  for (int i : contact.ownedSlaveNodes()) mine[i] = rank;
  if (size > 1)
    Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, static_cast<int>(numSlave), mine.data(), owner.data());
  else
    owner = mine;

  // 2. pack per destination
  std::vector<std::vector<double>> send(static_cast<std::size_t>(size));
  for (const NodalMortarEntry& e : local.entries) {
    const int i = contact.slaveNodeIndex(e.node);
    COULOMB_CHECK(i >= 0 && owner[i] >= 0, "mortar entry of node " + std::to_string(e.node + 1) +
                                                 " without an owning rank");
    pack(send[owner[i]], e);
  }

  // 3. exchange
  const std::vector<double> received = exchangeByRank(comm, std::move(send));

  // 4. unpack in rank order and sum
  std::map<long long, NodalMortarEntry> sum;
  Reader reader{received.data()};
  const double* end = received.data() + received.size();
  while (reader.p < end) {
    NodalMortarEntry e = unpack(reader);
    auto it = sum.find(e.node);
    if (it == sum.end())
      sum.emplace(e.node, std::move(e));
    else
      it->second.add(e);
  }
  result.entries.reserve(sum.size());
  for (auto& [node, entry] : sum) result.entries.push_back(std::move(entry));
  return result;
}

}  // namespace coulomb::contact
