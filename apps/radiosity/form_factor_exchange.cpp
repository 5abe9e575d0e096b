#include "apps/radiosity/form_factor_exchange.hpp"

#include <stdexcept>

namespace gcsim::radiosity {

FormFactorExchange parse_form_factor_exchange(const std::string& s) {
  if (s == "per-shooter") return FormFactorExchange::per_shooter;
  if (s == "together") return FormFactorExchange::together;
  throw std::invalid_argument("unknown form factor exchange '" + s + "' (expected per-shooter or together)");
}

const char* to_string(FormFactorExchange e) { return e == FormFactorExchange::together ? "together" : "per-shooter"; }

}  // namespace gcsim::radiosity
