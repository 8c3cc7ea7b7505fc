#pragma once
/// @file TpetraTypes.hpp
/// @brief Short names for the Tpetra types Coulomb uses (forward
/// declarations only: including this header costs nothing).
#include <Tpetra_CrsGraph_fwd.hpp>
#include <Tpetra_CrsMatrix_fwd.hpp>
#include <Tpetra_Export_fwd.hpp>
#include <Tpetra_Import_fwd.hpp>
#include <Tpetra_Map_fwd.hpp>
#include <Tpetra_MultiVector_fwd.hpp>
#include <Tpetra_Vector_fwd.hpp>

#include "coulomb/core/Types.hpp"

namespace coulomb {
using Map = Tpetra::Map<LocalOrdinal, GlobalOrdinal>;
using CrsGraph = Tpetra::CrsGraph<LocalOrdinal, GlobalOrdinal>;
using CrsMatrix = Tpetra::CrsMatrix<Scalar, LocalOrdinal, GlobalOrdinal>;
using Vector = Tpetra::Vector<Scalar, LocalOrdinal, GlobalOrdinal>;
using MultiVector = Tpetra::MultiVector<Scalar, LocalOrdinal, GlobalOrdinal>;
using Export = Tpetra::Export<LocalOrdinal, GlobalOrdinal>;
using Import = Tpetra::Import<LocalOrdinal, GlobalOrdinal>;
}  // namespace coulomb
