// The polar grid of one film (docs/physics.md section 10): Nr radial nodes including both
// edges, Nθ distinct circumferential nodes, periodic in θ. Cells lie between nodes;
// node areas are the integrals of the bilinear hat functions, so that quantities
// spread from cells to nodes with those hats sum exactly to the cell totals.
#pragma once

#include <vector>

namespace twb {

class FilmMesh {
 public:
  FilmMesh(double inner_radius, double outer_radius, int radial_nodes, int circumferential_nodes);

  int radial_nodes() const { return nr_; }
  int circumferential_nodes() const { return nt_; }
  int node_count() const { return nr_ * nt_; }
  int node(int i, int j) const { return i * nt_ + wrap(j); }
  int wrap(int j) const { return ((j % nt_) + nt_) % nt_; }
  // Interior nodes (radial 1 … Nr−2), which carry a film's pressures: ordinal
  // (i − 1)·Nθ + j, −1 on the edges.
  int interior_count() const { return nr_ > 2 ? (nr_ - 2) * nt_ : 0; }
  int interior_node(int i, int j) const { return i > 0 && i < nr_ - 1 ? (i - 1) * nt_ + wrap(j) : -1; }

  double inner_radius() const { return r_in_; }
  double outer_radius() const { return r_out_; }
  double dr() const { return dr_; }
  double dtheta() const { return dtheta_; }
  double radius(int i) const { return r_in_ + i * dr_; }
  double angle(int j) const { return j * dtheta_; }

  // ∫ hat_i(r) r dr · Δθ: the area a node stands for.
  double node_area(int i) const { return node_area_[i]; }
  // Area of the annulus; equals Σ node areas over all nodes.
  double area() const;

  // Linear interpolation weights of radius r onto this mesh's radial nodes, r clamped
  // to the annulus: r lies in [radius(i0), radius(i0+1)], weight of i0 is w0.
  struct RadialWeights { int i0; double w0; int i1; double w1; };
  RadialWeights radial_weights(double r) const;

 private:
  double r_in_, r_out_;
  int nr_, nt_;
  double dr_, dtheta_;
  std::vector<double> node_area_;
};

}  // namespace twb
