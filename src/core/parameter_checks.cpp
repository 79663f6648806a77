// The parameter checks shared by every curve kind (parameter_checks.hpp).
#include "casteljau/core/parameter_checks.hpp"

#include <string>

#include "casteljau/core/point_array.hpp"
#include "number_text.hpp"

namespace casteljau {
namespace {

using detail::number_text;

std::string domain_text(Interval domain) {
  return "[" + number_text(domain.lower) + ", " + number_text(domain.upper) + "]";
}

}  // namespace

Status check_split_parameter(double u, Interval domain) {
  if (auto ok = check_finite(u, "the split parameter"); !ok) return ok;
  if (!(domain.lower < u && u < domain.upper))
    return Error{"the split parameter " + number_text(u) + " is not strictly inside the domain " +
                 domain_text(domain), ErrorKind::out_of_domain};
  return {};
}

Status check_segment_parameters(double u0, double u1, Interval domain) {
  if (auto ok = check_finite(u0, "the segment's start"); !ok) return ok;
  if (auto ok = check_finite(u1, "the segment's end"); !ok) return ok;
  if (!domain.contains(u0) || !domain.contains(u1))
    return Error{"the segment [" + number_text(u0) + ", " + number_text(u1) + "] is not inside the domain " +
                 domain_text(domain), ErrorKind::out_of_domain};
  if (!(u0 < u1))
    return Error{"the segment [" + number_text(u0) + ", " + number_text(u1) + "] needs its start below its end"};
  return {};
}

}  // namespace casteljau
