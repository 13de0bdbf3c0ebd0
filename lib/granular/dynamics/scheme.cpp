#include "granular/dynamics/scheme.hpp"

#include "granular/detail/enum_names.hpp"
#include "granular/error.hpp"

namespace granular {
namespace {

// a1 b1 … am bm am … b1 a1 from the half sequences a1…am, b1…bm (bm is the middle kick).
SplittingScheme palindrome(std::string name, const std::vector<double>& a, const std::vector<double>& b, int order) {
  SplittingScheme s;
  s.name = std::move(name);
  s.order = order;
  s.drift = a;
  s.kick = b;
  for (std::size_t i = a.size(); i-- > 0;) s.drift.push_back(a[i]);
  for (std::size_t i = b.size() - 1; i-- > 0;) s.kick.push_back(b[i]);
  return s;
}

}  // namespace

SplittingScheme saba2c() {
  SplittingScheme s = saba2();
  s.name = "saba2c";
  s.corrector = 0.01116454968463011276968973577058865137738;  // (2 − √3)/24
  s.order = 4;
  return s;
}

SplittingScheme saba2() {
  const double c1 = 0.2113248654051871177454256097490212721762;  // 1/2 − √3/6
  const double c2 = 0.5773502691896257645091487805019574556476;  // √3/3
  SplittingScheme s;
  s.name = "saba2";
  s.drift = {c1, c2, c1};
  s.kick = {0.5, 0.5};
  s.order = 2;
  return s;
}

SplittingScheme aba864() {
  return palindrome("aba864",
                    {0.0711334264982231177779387300061549964174, 0.241153427956640098736487795326289649618,
                     0.521411761772814789212136078067994229991, -0.333698616227678005726562603400438876027},
                    {0.183083687472197221961703757166430291072, 0.310782859898574869507522291054262796375,
                     -0.0265646185119588006972121379164987592663, 0.0653961422823734184559721793911134363710},
                    4);
}

SplittingScheme srkn14a() {
  std::vector<double> a = {0.0378593198406116, 0.102635633102435, -0.0258678882665587, 0.314241403071447,
                           -0.130144459517415, 0.106417700369543, -0.00879424312851058};
  std::vector<double> b = {0.09171915262446165,  0.183983170005006, -0.05653436583288827,
                           0.004914688774712854, 0.143761127168358, 0.328567693746804};
  double sa = 0, sb = 0;
  for (double x : a) sa += x;
  for (double x : b) sb += x;
  a.push_back(1 - 2 * sa);  // a8 (middle drift)
  b.push_back(0.5 - sb);    // b7
  // a1 b1 … a7 b7 a8 b7 a7 … b1 a1
  SplittingScheme s;
  s.name = "srkn14a";
  s.order = 6;
  s.drift = a;
  for (std::size_t i = a.size() - 1; i-- > 0;) s.drift.push_back(a[i]);
  s.kick = b;
  for (std::size_t i = b.size(); i-- > 0;) s.kick.push_back(b[i]);
  return s;
}

SplittingScheme parse_scheme(std::string_view name, const std::string& parameter) {
  static constexpr auto names = detail::enum_names<SplittingScheme (*)()>(
      "scheme", {{saba2c, "saba2c"}, {saba2, "saba2"}, {aba864, "aba864"}, {srkn14a, "srkn14a"}}, true);
  return names.parse(name, parameter)();
}

}  // namespace granular
