#pragma once
/// @file LinearSolverFactory.hpp
/// @brief Builds the Stratimikos linear solver from the deck's "Linear
/// Solver" sublist (Belos, MueLu, Ifpack2, Amesos2 all registered), with
/// Coulomb's defaults filled in where the user said nothing.
#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>
#include <Thyra_LinearOpWithSolveFactoryBase.hpp>

#include "coulomb/core/TpetraTypes.hpp"

namespace coulomb::fem {
struct VertexCoarsening;
}

namespace coulomb::solver {

/// @brief The defaults: Belos Pseudo Block CG preconditioned by MueLu
/// (plain aggregation with rigid-body modes, Chebyshev smoothing,
/// coarsest level gathered on one rank and factored by KLU2,
/// which is wrong when distributed in Debian's 13.2).
/// Below 5000 DoFs the preconditioner is Ifpack2 symmetric Gauss-Seidel
/// instead (tiny hierarchies are fragile, see the .cpp).
/// `symmetric` false (contact with condensed multipliers: the gap rows make
/// the tangent nonsymmetric): Belos Pseudo Block GMRES instead of CG, and
/// Gauss-Seidel smoothing in MueLu instead of Chebyshev (whose eigenvalue
/// bounds assume a symmetric matrix).
/// `cornerDofs`: the DoFs of the corner nodes of a mesh with quadratic
/// cells (fem::cornerNodeCount x dofsPerNode; 0 for a linear mesh). From
/// 5000 on, the preconditioner is "P-Multigrid" (PMultigrid.hpp): the same
/// MueLu on the corner nodes under a p-coarsening; a deck naming "MueLu"
/// still gets the MueLu keys.
Teuchos::RCP<Teuchos::ParameterList> defaultLinearSolverParameters(int dofsPerNode, long long numGlobalDofs,
                                                                   bool symmetric = true, long long cornerDofs = 0);

/// @brief Stratimikos builder output plus the MueLu (or P-Multigrid)
/// sublist where the near-null space and coordinates must be set again
/// before each setup (MueLu's Thyra adapter removes them once used).
struct LinearSolver {
  Teuchos::RCP<Thyra::LinearOpWithSolveFactoryBase<double>> factory;
  Teuchos::RCP<Teuchos::ParameterList> parameters;  ///< the full, completed Stratimikos list
  bool usesMueLu = false;
  bool usesPMultigrid = false;  ///< MueLu under a p-coarsening (PMultigrid.hpp)
  bool isDirect = false;
};

/// @brief Completes `user` with the defaults and builds the factory. Throws
/// coulomb::Error (one line) if Stratimikos rejects the list. "Amesos2" is
/// served by GatheredDirectSolverFactory (factored on one rank) at any rank count.
LinearSolver buildLinearSolver(const Teuchos::ParameterList& user, int dofsPerNode,
                               long long numGlobalDofs, bool symmetric = true, long long cornerDofs = 0);

/// @brief Puts rigid-body modes (3 in 2D, 6 in 3D) and nodal coordinates
/// into the MueLu sublist of `solver`, as MueLu's "Nullspace"/"Coordinates";
/// with P-Multigrid, the corner level `vertices` into its sublist.
void setMueLuUserData(LinearSolver& solver, const Teuchos::RCP<MultiVector>& nullspace,
                      const Teuchos::RCP<MultiVector>& coordinates, const fem::VertexCoarsening* vertices = nullptr);

}  // namespace coulomb::solver
