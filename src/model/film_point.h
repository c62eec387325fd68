// The film at any point of a solved state, between its nodes (docs/physics.md sections 7
// and 8): the gap, the asperity contact, the heat generated there, the two faces'
// temperatures and the film temperature that balances that heat against its conduction
// to the faces. The oil's peak temperature and the asperities' contact temperature are
// located on these point values rather than read from the node nearest the hot spot: a
// film node's heat is its control volume's (its hat's) mean, and at the tight rim,
// where the contact heat rises steeply to the edge, that mean lags the rim's value by a
// part of a cell, so the hottest node converges with the mesh at first order at best.
#pragma once

#include <array>
#include <span>
#include <vector>

#include "model/bearing_model.h"
#include "model/film_gap.h"
#include "model/film_roughness.h"
#include "physics/flash_temperature.h"

namespace twb {

struct FilmTotals;

struct FilmPoint {
  double gap = 0.0;               // h (m), with the deformation and the relief
  double mean_gap = 0.0;          // h̄T (m)
  double contact_pressure = 0.0;  // p_cont (Pa), nominal
  double sliding_speed = 0.0;     // V = |ω| r (m/s); 0 on the film that does not slide
  double heat = 0.0;              // W/m² generated: f p_cont V + μ V²/h̄T
  double film_temperature = 0.0;  // Tf (K)
  // The lower and the upper body's temperature there (the washer's mid-plane), and their
  // faces' on the heat path from Tf (K).
  std::array<double, 2> body_temperature{}, face_temperature{};
  // On the sliding film where asperities touch: Blok's flash temperature rise of the mean
  // summit contact (physics/flash_temperature.h), and the contacts' temperature, the faces'
  // mean plus that rise (K; the faces' mean where nothing touches).
  double flash_rise = 0.0, contact_temperature = 0.0;
};

class FilmPointReader {
 public:
  // A solved state u and its films' totals (the sliding film's friction coefficient, and
  // with convection the nodes' heat).
  FilmPointReader(const BearingModel& model, std::span<const double> u, std::span<const FilmTotals> totals);

  // The point (r, θ) of a film, r within its annulus.
  FilmPoint at(const Film& film, double r, double theta) const;

 private:
  const BearingModel& model_;
  std::span<const double> u_;
  double friction_coefficient_ = 0.0;
  // With convection, per film and node, the heat per unit area the oil carries away from
  // the node's volume (W/m²): its generation less its conduction to the faces, what the
  // node's balance gives the advection (physics §15); empty without convection.
  std::vector<std::vector<double>> advected_;
  std::vector<FilmGap> gaps_;  // each film's gap at u
  std::vector<FilmRoughness> roughness_;  // and its roughness (where its faces run in, per node)
  // The bodies a film's contacts heat, by ComponentId (carrier, washer, gear): their
  // conductivity and diffusivity; the softer one carries the summits' junctions with it.
  std::array<FlashBody, 3> flash_bodies_{};
  std::array<double, 3> yield_strength_{};
  // `scale`: the summits' k = σ/σ0 at the point where the faces run in (section 20), else 1.
  double flash_rise(const Film& film, double gap, double scale, double contact_pressure, double sliding_speed) const;
  std::vector<double> node_advection(const Film& film, const FilmTotals& totals) const;
};

}  // namespace twb
