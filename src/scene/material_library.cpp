// The materials twb ships, with the sources of their values (docs/materials.md). A value
// a source does not give is a handbook figure and the sources say so: a user with the
// supplier's sheet overrides it field by field.
#include "twb/scene/material_library.h"

#include <algorithm>

namespace twb {
namespace {

constexpr double kGPa = 1e9, kMPa = 1e6;

constexpr double celsius(double t) { return t + 273.15; }

ModulusAt at(double t_celsius, double e_gpa) { return {celsius(t_celsius), e_gpa * kGPa}; }

Material material(double e, double nu, double yield, double k, double rho, double c, double alpha,
                  std::optional<double> limit_celsius, std::optional<double> pv_mpa_m_s = std::nullopt) {
  Material m;
  m.youngs_modulus = e;
  m.poisson_ratio = nu;
  m.yield_strength = yield;
  m.conductivity = k;
  m.density = rho;
  m.specific_heat = c;
  m.thermal_expansion = alpha;
  if (limit_celsius) m.max_temperature = celsius(*limit_celsius);
  if (pv_mpa_m_s) m.pv_limit = *pv_mpa_m_s * kMPa;
  return m;
}

// A polymer's modulus over temperature (physics §23): from its data sheet, starting at
// the room-temperature modulus its table row gives.
Material with_modulus_curve(Material m, std::vector<ModulusAt> curve) {
  m.modulus_by_temperature = std::move(curve);
  return m;
}

std::vector<LibraryMaterial> shipped_materials() {
  std::vector<LibraryMaterial> all;
  all.push_back({"paper_steel", "the paper's steel (Table 1), every body's default", MaterialForm::bulk,
                 Material{}, std::nullopt, std::nullopt,
                 "E, nu, S_y, K and the expansion: Jackson and Green (2006), Table 1. Density and heat capacity: an "
                 "ordinary carbon steel (the paper has none; they matter in transients only)."});
  all.push_back({"bearing_steel", "100Cr6 (AISI 52100), through-hardened to 60-64 HRC", MaterialForm::bulk,
                 material(208 * kGPa, 0.30, 2.0 * kGPa, 46.6, 7810, 470, 11.9e-6, 120.0), std::nullopt,
                 std::nullopt,
                 "E 190-210 GPa and nu 0.27-0.30 (suppliers' 52100/SUJ2 sheets; 208 GPa as rolling-bearing "
                 "catalogues take it); yield: the hardened steel's compressive yield, about 2 GPa (ASM Handbook vol. "
                 "1, a handbook figure); K 46.6 W/(m K), density 7810, expansion 11.9e-6 1/K (suppliers' SAE 52100 "
                 "sheets), c 470 J/(kg K) (MakeItFrom, SAE-AISI 52100); limit 120 degC: the dimensional stability "
                 "of the standard heat treatment (bearing catalogues; stabilised to S1/S2, 200/250 degC: override "
                 "max_temperature)."});
  all.push_back({"cusn8", "CuSn8 phosphor bronze (CW453K, C52100), strip R540", MaterialForm::bulk,
                 material(115 * kGPa, 0.34, 460 * kMPa, 62.0, 8800, 370, 18.0e-6, 180.0, 1.75), std::nullopt,
                 std::nullopt,
                 "E 110-115 GPa, K 62 W/(m K), density 8800, expansion 18e-6 1/K (EN 1652 CW453K suppliers' sheets; "
                 "MakeItFrom, UNS C52100); nu 0.34, c 370 J/(kg K), limit 180 degC (MakeItFrom: the mechanical "
                 "maximum); yield Rp0.2 >= 460 MPa, temper R540 (DIN 17670 / EN 1652 table: R450 280, R600 530 "
                 "MPa); PV 1.75 MPa m/s: a lubricated bronze bushing's usual limit, not CuSn8's own."});
  all.push_back({"peek", "PEEK, unfilled (Victrex 450G class)", MaterialForm::bulk,
                 with_modulus_curve(material(3.7 * kGPa, 0.40, 118 * kMPa, 0.29, 1300, 1340, 48e-6, 250.0),
                 {at(23, 3.7), at(100, 3.4), at(140, 3.0), at(150, 1.5), at(160, 0.6), at(200, 0.45), at(250, 0.35)}),
                 celsius(143), std::nullopt,
                 "E 3.6-3.7 GPa (ISO 527; the 450G data sheet 3.7), compressive yield 118 MPa (ISO 604), K 0.29 "
                 "W/(m K) (Victrex 450G data sheet; 0.25 in older compilations); density 1300, expansion 48e-6 1/K "
                 "below T_g, T_g 143 degC (Crawford, Plastics Engineering, table 1.8); limit 250 degC: continuous "
                 "service (Hufenbach et al., PEEK-PTFE blends; UL RTI 240-260 degC); nu 0.40 and c 1340 J/(kg K) "
                 "at 23 degC: handbook figures. E(T): approximate points of the typical modulus-temperature curve "
                 "of unfilled PEEK (the supplier's flexural modulus against temperature, as handbooks reproduce "
                 "it; not read off the sheet itself: the fall through the glass transition between 143 and 160 "
                 "degC is the feature to trust, not the second digit). No PV limit: the supplier tabulates a "
                 "limiting PV by speed, not one value; give yours as pv_limit."});
  all.push_back({"peek_cf30", "PEEK with 30 % carbon fibre and 15 % PTFE, a bearing grade (LATI Latilub "
                 "88-10-15T K-30)",
                 MaterialForm::bulk,
                 with_modulus_curve(material(22.8 * kGPa, 0.40, 210 * kMPa, 0.95, 1480, 1300, 15e-6, 255.0),
                                    {at(23, 22.8), at(60, 22.0), at(90, 20.0), at(120, 17.6), at(150, 13.2)}), celsius(143), std::nullopt,
                 "E and E(T) 23-150 degC (ISO 527, 1 mm/min), tensile strength 210 MPa at break (taken as its "
                 "yield: the composite breaks before it yields), density 1480, expansion 5e-6 along the flow and "
                 "25e-6 1/K across it (ISO 11359; 15e-6 their mean): LATI's data sheet for Latilub 88-10-15T K-30; "
                 "limit 255 degC: 30 % carbon PEEK (Crawford, table 1.8); K 0.95 W/(m K) (Victrex 450CA30 class), "
                 "nu 0.40 and c 1300 J/(kg K) (by mixtures): handbook figures. Anisotropic: across the flow the "
                 "modulus is lower."});
  all.push_back({"pa46", "PA46, unfilled, heat-stabilised, dry as moulded (Stanyl TW341 class)", MaterialForm::bulk,
                 material(3.3 * kGPa, 0.40, 100 * kMPa, 0.30, 1180, 2100, 80e-6, 150.0), celsius(74),
                 std::nullopt,
                 "E 3.3 GPa, K 0.30 W/(m K), density 1180-1210, c 2.1 J/(g K), expansion 70-80e-6 1/K, T_g 74 "
                 "degC dry by DSC (lower when moist): NETZSCH polymer database, PA46; yield 100 MPa dry, nu 0.40 "
                 "and the 150 degC long-term limit: handbook figures for heat-stabilised PA46 (conditioned at 50 % "
                 "RH its modulus falls to 1.0-1.3 GPa: override youngs_modulus). No E(T) and no PV limit in the "
                 "sources read."});
  all.push_back({"ppa", "PPA (polyphthalamide), unfilled (Amodel class)", MaterialForm::bulk,
                 material(3.3 * kGPa, 0.41, 100 * kMPa, 0.25, 1160, 1400, 60e-6, 150.0), celsius(125),
                 std::nullopt,
                 "T_g 123-135 degC (by the test method) and the continuous-use limit (150-185 degC for 5000 h, "
                 "130-165 degC for 20000 h; the lower 5000 h figure taken): the supplier's launch data (Plastics "
                 "Technology, 'More on that new polyphthalamide'); E, nu, yield, K, density, c and expansion: "
                 "handbook figures for unfilled PPA, of low confidence: take them from the supplier's design guide "
                 "where it matters."});
  all.push_back({"ptfe_glass25", "PTFE, 25 % glass fibre", MaterialForm::bulk,
                 material(1.2 * kGPa, 0.42, 8 * kMPa, 0.42, 2240, 960, 90e-6, 260.0, 0.35), std::nullopt,
                 std::nullopt,
                 "yield: compressive strength at 1 % deformation 7.4-8.3 MPa (ASTM D695), density 2220-2250: "
                 "suppliers' tables of filled PTFE; limit 250-260 degC (Crawford, table 1.8; suppliers); E 1.0-1.5 "
                 "GPa, nu 0.42, K 0.4-0.45 W/(m K), c (by mixtures), expansion 80-100e-6 1/K and the dry PV limit "
                 "0.35 MPa m/s: handbook figures of low confidence. Unfilled PTFE: E 0.4-0.8 GPa, K 0.25."});
  all.push_back({"ptfe_coating", "a resin-bonded PTFE anti-friction coating", MaterialForm::coating,
                 material(2.0 * kGPa, 0.40, 40 * kMPa, 0.25, 1800, 1000, 80e-6, 260.0), std::nullopt,
                 std::pair{3e-6, 42e-6},
                 "thickness: dry-film lubricants 2.5-13 um, PTFE coatings studied from 3 to 42 um; service to 285 "
                 "degC for the coating family, 260 degC for its PTFE (Whitford Xylan brochure); E, nu, yield, K, "
                 "density, c and expansion depend on the binder: handbook figures of low confidence."});
  all.push_back({"manganese_phosphate", "a manganese phosphate conversion coating (MIL-DTL-16232 type M)",
                 MaterialForm::coating, material(40 * kGPa, 0.30, 200 * kMPa, 1.0, 2500, 750, 12e-6, 121.0),
                 std::nullopt, std::pair{5e-6, 25e-6},
                 "limit 121 degC: MIL-DTL-16232G 6.1.1; porous crystalline hureaulite that holds oil (it forms "
                 "poorly on steels above 1 % Cr, as 100Cr6); thickness 5-25 um (heavy phosphate, the "
                 "specification's coating weights); E, nu, yield, K, density, c and expansion: estimates of very "
                 "low confidence, no measured values found: a layer's thermal resistance t/K is what matters."});
  return all;
}

}  // namespace

std::span<const LibraryMaterial> material_library() {
  static const std::vector<LibraryMaterial> library = shipped_materials();
  return library;
}

const LibraryMaterial* find_library_material(std::string_view name) {
  const std::span<const LibraryMaterial> all = material_library();
  const auto found = std::find_if(all.begin(), all.end(), [&](const LibraryMaterial& m) { return m.name == name; });
  return found == all.end() ? nullptr : &*found;
}

std::vector<std::string_view> library_material_names(MaterialForm form) {
  std::vector<std::string_view> names;
  for (const LibraryMaterial& m : material_library())
    if (m.form == form) names.push_back(m.name);
  return names;
}

}  // namespace twb
