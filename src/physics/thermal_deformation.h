// Thermal deformation of the three bodies (docs/physics.md section 11): only the shapes of the
// films change; the bodies stay otherwise rigid.
#pragma once

namespace twb {

// Carrier and gear (thick plates, back face at ambient): with a linear temperature
// profile from the face's T to T0 at the back, the face moves towards the film by
// u = c_ν·α·t·(T − T0)/2, with c_ν = 1 for laterally free columns (the default) or
// (1+ν)/(1−ν) when laterally constrained (the hot spot held by the cool plate around
// it). Returns du/dT = c_ν·α·t/2 (m/K).
double face_expansion_per_kelvin(double expansion, double thickness, double poisson_ratio, bool constrained);

// Washer (thin, free): a heat flux q_w crossing it from its film-1 face to its film-2
// face makes the faces differ by ΔT = q_w·t_w/K_w, and the free washer bends with the
// curvature κ = α·ΔT/t_w = α·q_w/K_w. Returns dκ/dq_w = α/K_w (1/m per W/m²).
double dishing_curvature_per_flux(double expansion, double conductivity);

// The dished washer's mid-surface relative to its rigid-body plane, for the area-mean
// curvature κ̄ over the annulus [r_i, r_o]: w(r) = κ̄·(r² − ⟨r²⟩)/2 with the area mean
// ⟨r²⟩ = (r_i² + r_o²)/2, so that w has zero mean over the washer and z_w, γx, γy keep
// their meaning. Positive towards film 2. Returns dw/dκ̄ at r (m²).
double dishing_shape(double r, double inner_radius, double outer_radius);

}  // namespace twb
