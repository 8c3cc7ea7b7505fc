#include "coulomb/contact/laws/CondensationFrame.hpp"

namespace coulomb::contact {

template CondensationFrame<2> condensationFrame<2>(const std::array<double, 2>&, const std::array<bool, 2>&);
template CondensationFrame<3> condensationFrame<3>(const std::array<double, 3>&, const std::array<bool, 3>&);

}  // namespace coulomb::contact
