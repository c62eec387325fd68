#include "model/reynolds_operator.h"
#include "twb/error_family.h"

#include <stdexcept>

namespace twb {

int ReynoldsOperator::interior_count() const { return mesh_.interior_count(); }

int ReynoldsOperator::interior_index(int i, int j) const { return mesh_.interior_node(i, j); }

ReynoldsOperator::ControlVolume ReynoldsOperator::control_volume(int i, int j) const {
  const double r = mesh_.radius(i), th = mesh_.angle(mesh_.wrap(j));
  return {r - 0.5 * mesh_.dr(), r + 0.5 * mesh_.dr(), th - 0.5 * mesh_.dtheta(), th + 0.5 * mesh_.dtheta()};
}

double ReynoldsOperator::radial_geometry(int i) const {
  const double rf = mesh_.radius(i) + 0.5 * mesh_.dr();
  return rf * mesh_.dtheta() / mesh_.dr();
}

double ReynoldsOperator::circumferential_geometry(int i) const {
  return mesh_.dr() / (mesh_.radius(i) * mesh_.dtheta());
}

int ReynoldsOperator::radial_face_count() const {
  return mesh_.radial_nodes() > 2 ? (mesh_.radial_nodes() - 1) * mesh_.circumferential_nodes() : 0;
}

int ReynoldsOperator::face_count() const { return radial_face_count() + interior_count(); }

ReynoldsFace ReynoldsOperator::radial_face(int i, int j) const {
  j = mesh_.wrap(j);
  const int nt = mesh_.circumferential_nodes();
  return {ReynoldsFace::Kind::radial, i * nt + j, i, j, i + 1, j, interior_index(i, j), interior_index(i + 1, j),
          mesh_.radius(i) + 0.5 * mesh_.dr(), mesh_.angle(j), radial_geometry(i), 0.0};
}

ReynoldsFace ReynoldsOperator::circumferential_face(int i, int j) const {
  j = mesh_.wrap(j);
  const int jb = mesh_.wrap(j + 1);
  return {ReynoldsFace::Kind::circumferential, radial_face_count() + interior_index(i, j), i, j, i, jb,
          interior_index(i, j), interior_index(i, jb), mesh_.radius(i), mesh_.angle(j) + 0.5 * mesh_.dtheta(),
          circumferential_geometry(i), mesh_.dr()};
}

ReynoldsFace ReynoldsOperator::edge_face(int i, int j) const {
  j = mesh_.wrap(j);
  return {ReynoldsFace::Kind::circumferential, -1, i, j, i, mesh_.wrap(j + 1), -1, -1, mesh_.radius(i),
          mesh_.angle(j) + 0.5 * mesh_.dtheta(), 0.0, 0.5 * mesh_.dr()};
}

ReynoldsFaceFlux ReynoldsOperator::flux(const ReynoldsFace& face, double omega, double g, double carried,
                                        double pa, double pb) {
  const double dp = pb - pa;
  // Sliding speed ω r; the moving surface drags half of it across the gap (Couette).
  const double couette = 0.5 * omega * face.r * face.couette_width;
  return {-g * face.geometry * dp + couette * carried, -face.geometry * dp, couette, g * face.geometry,
          -g * face.geometry};
}

std::vector<double> ReynoldsOperator::net_outflow(double omega, std::span<const double> conductance,
                                                  std::span<const double> carried,
                                                  std::span<const double> pressure) const {
  if (int(conductance.size()) != face_count() || int(carried.size()) != face_count() ||
      int(pressure.size()) != interior_count())
    throw InternalError("ReynoldsOperator::net_outflow: array sizes do not match the mesh");
  std::vector<double> w(pressure.size(), 0.0);
  auto p = [&](int k) { return k >= 0 ? pressure[k] : 0.0; };  // ambient on the edges
  for_each_face([&](const ReynoldsFace& f) {
    const double c = f.kind == ReynoldsFace::Kind::circumferential ? carried[f.index] : 0.0;
    const ReynoldsFaceFlux q = flux(f, omega, conductance[f.index], c, p(f.a), p(f.b));
    for (const auto [node, sign] : f.ends())
      if (node >= 0) w[node] += sign * q.q;
  });
  return w;
}

std::vector<ReynoldsOperator::Coefficient> ReynoldsOperator::pressure_coefficients(
    std::span<const double> conductance) const {
  if (int(conductance.size()) != face_count())
    throw InternalError("ReynoldsOperator::pressure_coefficients: array size does not match the mesh");
  std::vector<Coefficient> m;
  m.reserve(std::size_t(face_count()) * 4);
  for_each_face([&](const ReynoldsFace& f) {
    const ReynoldsFaceFlux q = flux(f, 0.0, conductance[f.index], 0.0, 0.0, 0.0);
    for (const auto [node, sign] : f.ends()) {
      if (node < 0) continue;
      if (f.a >= 0) m.push_back({node, f.a, sign * q.dq_dpa});
      if (f.b >= 0) m.push_back({node, f.b, sign * q.dq_dpb});
    }
  });
  return m;
}

}  // namespace twb
