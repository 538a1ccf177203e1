// SPDX-License-Identifier: MIT
// The embedded default configuration: the paper's 20.1 mg/cm2 case in the full 75 x 75 um box
// (Lippke et al. 2022; every number from model.md). Kept equal to Config{} by a unit test.
#include "drydem/io/config.hpp"

namespace drydem {

std::string_view default_config_toml() {
    return R"toml(# DryDEM configuration: the paper's 20.1 mg/cm2 case (Lippke et al., Energy Technol. 2022).
# Values are SI numbers or strings with units ("6.5 um", "20.1 mg/cm^2", "1.801 Pa*s", "40 deg").

[run]
name = "lippke2022-20.1mgcm2"
seed = 12345
time_step = 0                # largest scaled time step; 0 = 1e-10 s (semi_implicit) or 1e-11 s
                             # (explicit); the stability guard may lower it (docs/model.md)
threads = 0                  # 0 = all cores
max_process_time = "300 s"   # safety stop (physical time)

[film]
areal_loading = "20.1 mg/cm^2"   # dry coating mass per area
solids_mass_fraction = 0.70      # x_s of the slurry
box_x = "75 um"                  # periodic base (>= 36 um, model.md M-2.5)
box_y = "75 um"

[formulation]
ncm_mass_fraction = 0.94
pvdf_mass_fraction = 0.03
cb_mass_fraction = 0.03
ncm_diameters = ["6.50 um", "7.58 um", "8.60 um", "9.82 um", "11.35 um"]  # equal-volume classes
cb_diameter = "1.5 um"
cb_porosity = 0.75               # CB agglomerate porosity (calibrated, paper Sec. 9)

[materials]
ncm_density = "4.74 g/cm^3"
cb_density = "1.66 g/cm^3"       # solid carbon; particles carry pore NMP (model.md M-1.3)
pvdf_density = "1.78 g/cm^3"     # C-1
solvent_density = "1.03 g/cm^3"  # NMP
viscosity = "1.801 Pa*s"         # PVDF-in-NMP liquid
surface_tension = "0.041 N/m"
contact_angle = "40 deg"
ncm_youngs_modulus = "142 GPa"
cb_youngs_modulus = "142 GPa"    # C-9
poisson_ratio = 0.3              # C-10
substrate_youngs_modulus = "70 GPa"  # aluminium current collector, C-8
substrate_poisson_ratio = 0.33

[contact]
friction = 0.8                   # calibrated sliding friction, all pairs
substrate_friction = 0.8         # C-6
restitution = 0.5                # C-11
rolling_friction = 0.0           # C-7 (off)

[van_der_waals]                  # physical Hamaker constants; scaled by scaling.hamaker_factor
hamaker_cb_cb = "4.64e-20 J"
hamaker_ncm_cb = "9.5e-20 J"     # C-12: the paper prints 9.5e-19 J (probable typo)
hamaker_ncm_ncm = "2.11e-19 J"
min_gap_cb_cb = "5 nm"
min_gap_ncm_cb = "10 nm"
min_gap_ncm_ncm = "50 nm"
cutoff = 0                       # 0 = each pair's lubrication range r_L (C-13)

[lubrication]
enabled = true
substrate = true
kappa_c = 0.1
uses_reduced_viscosity = false   # C-17

[double_layer]                   # electrostatic double-layer repulsion (DLVO, docs/model.md); the
enabled = false                  # paper leaves it out (van der Waals dominates); scaled like van der Waals
surface_potential = "-25 mV"     # psi_0 of every particle (a zeta potential; measure it for your slurry)
debye_length = "100 nm"          # lambda_D of the liquid (from its ionic strength; illustrative)
relative_permittivity = 32.2     # NMP at 25 degC
cutoff = 0                       # 0 = each pair's lubrication range r_L, as van der Waals

[scaling]                        # the paper's time-scaling scheme (Sec. 4.1, model.md M-7)
time_factor = 1e7                # k
viscosity_reduction = 10         # b (Stokes drag viscosity / b)
capillary_factor = 9e3
hamaker_factor = 1e7
gravity = "9.81 m/s^2"           # physical; simulated g = g k / b

[dryer]                          # paper Table 2, 20.1 mg/cm2
shrinkage_rates = ["0.670 um/s", "1.193 um/s"]   # film shrinkage per zone (the DEM's liquid level)
line_speed = "2 m/min"
zone_length = "2 m"              # zone length of the DEM liquid-level schedule
schedule = "rates"               # DEM level from shrinkage_rates ("rates", reproduces the paper's DEM)
                                 # or from the dryer model below ("model"; docs/dryer.md)
# The dryer model (docs/dryer.md, dryer.md D-1 ... D-6; paper Sec. 6 and Table A1):
preset = "table2"                # "table2": n = 0.42, calibrated to Table 2; "physical": n = 1/3
zone_lengths = ["2 m", "2 m", "2 m"]
air_temperatures = ["80 degC", "100 degC", "120 degC"]
heat_transfer_coefficients = ["40 W/(m^2*K)", "40 W/(m^2*K)", "55 W/(m^2*K)"]  # top, per zone
bottom_heat_transfer_factor = 1.0  # bottom = factor * top coefficient (assumption A1)
analogy_exponent = 0             # n of beta = alpha/(rho c_p) Le^(n-1); 0 = the preset's value
initial_film_temperature = "25 degC"  # wet film at the dryer inlet (A4)
substrate_thickness = "20 um"    # aluminium foil (A3)
substrate_density = "2.7 g/cm^3"
substrate_heat_capacity = "900 J/(kg*K)"
supply_air_solvent_mole_fraction = 0.0  # NMP in the supply air (A2)
final_porosity = 0.44            # end of shrinkage; first guess of the dryer <-> DEM coupling
vapour_pressure = "anchored"     # NMP vapour pressure: "anchored" (Table A1) or "landolt" (+13 %)
ackermann = false                # Ackermann correction of the top heat flux
time_step = "0.02 s"             # RK4 step of the dryer model (<= 0.05 s)
coupling_tolerance = "0.5 um"    # coupling stops when the final thickness changes less than this
coupling_max_iterations = 6

[drying]
final_gap = 0                    # end criterion top - level; 0 = largest particle diameter (M-8.2)
relaxation = "10 s"              # physical time after the final thickness (C-22)
fluid_forces_above_level = "keep"  # C-19

[study]                          # drydem study: loadings x shrinkage-rate factors x seeds (paper Fig. 6)
loadings = []                    # e.g. ["20.1 mg/cm^2", "25.2 mg/cm^2"]; empty = film.areal_loading
shrinkage_rate_factors = []      # drying-rate study, e.g. [0.5, 1, 2] x dryer.shrinkage_rates (schedule "rates")
seeds = 3                        # runs per loading: seeds run.seed, run.seed + 1, ...
measured_loadings = []           # measured points plotted beside the simulation (optional)
measured_thickness = []          # one per measured loading, e.g. "84 um"
measured_thickness_std = []      # empty or one per measured loading
measured_density = []            # empty or one per measured loading, e.g. "2.4 g/cm^3"
measured_density_std = []

[numerics]
skin = 0                         # neighbour skin; 0 = 0.1 um (explicit) or 0.3 um (semi_implicit:
                                 # its longer steps would rebuild the list every few dozen steps)
overlap_limit = 1.0              # stop (runaway overlap) when an overlap reaches this fraction of the smaller radius
integrator = "semi_implicit"     # semi_implicit: v += dt (M + dt D)^-1 F, the viscous forces do not
                                 # limit dt; explicit: velocity Verlet, the reference (docs/model.md)
stability_guard = "adapt"        # adapt: dt = the guarded step (never above run.time_step);
                                 # refuse: stop beyond the stability bound; warn: only warn
sort_every = 10                  # spatial re-sort every N neighbor rebuilds

[calibration]                    # drydem calibrate (docs/calibration.md); parameters and targets as
                                 # [[calibration.parameters]] key = "contact.friction" min = 0.4 max = 1.2
                                 # [[calibration.targets]] quantity = "final_thickness" value = "83.8 um" uncertainty = "2 um"
seeds = 1                        # runs per evaluation (seeds run.seed, run.seed + 1, ...)
initial_points = 0               # space-filling start (SciPy qmc); 0 = max(4, 2 x parameters)
evaluations = 20                 # evaluations in all, the start included
sampler = "sobol"                # "sobol" or "lhs" (Latin hypercube)

[scheduler]                      # where drydem study / calibrate run their runs
type = "local"                   # "local": child processes (--jobs); "slurm": one Slurm job array per batch
partition = ""                   # sbatch --partition ("" = the cluster's default)
time_limit = "0 s"               # sbatch --time per task; 0 = the partition's default
cpus_per_task = 1                # sbatch --cpus-per-task = threads per run
resubmits = 3                    # a task stopped at its time limit is resubmitted and resumes, up to N times

[analysis]                       # structure analysis of final.csv at the end of a run (= drydem analyze)
at_end = true
voxel_size = "0.1 um"            # voxel edge of the pore analysis; 0 = only thickness, profiles, coordination
profile_dz = "0.5 um"            # slab width of the height profiles
contact_gap = "0 um"             # coordination: surface gap still counted as a contact (0 = touching)
pore_top = "half_solid"          # pore statistics below the half-solid height ("highest": below the highest top)
transport_voxel_sizes = ["0.8 um", "0.4 um", "0.2 um"]  # tortuosity / conductivity solves, one voxelization
                                 # each: the list shows the voxel-size convergence, the finest solved is
                                 # reported; [] = none (docs/analysis.md)
transport_max_voxels = 25000000  # a voxel size with more voxels is skipped (~400 bytes per voxel at peak)
ncm_conductivity = 0.01          # electronic conductivity of NCM [S/m] (an input: lithiated NCM622 ~1e-4..1e-1)
cb_conductivity = 100            # electronic conductivity of a CB agglomerate, carbon + binder + pores [S/m]
surface_points = 400             # points per NCM sphere for its surface split (0 = none)
cb_coverage_gap = "0.1 um"       # NCM surface within this distance of a CB agglomerate counts as covered
binder_diffusivity = 6.5e-12     # dissolved PVDF in NMP [m^2/s]: Stokes-Einstein, 20 nm, 1.67 mPa s, 298 K (binder migration)

[output]
timeseries_every = "0.5 s"       # physical time between time-series rows
snapshot_every = "10 s"          # physical time between snapshots (0 = only the final one)
progress_every = "10 s"          # wall-clock time between progress lines
checkpoint_every = "10 min"      # wall-clock time between checkpoints (drydem run --resume DIR); 0 = none
)toml";
}

} // namespace drydem
