// Every wheel's Jacobian (wrc/wheelset/contact.hpp: Jacobian; docs/guide/sensitivity.md): per area, the normal
// problem's linearised response to the wheelset's rigid motion in y, z, roll and yaw, then the tangential solver's
// linearisation for a change of the creepages and for what that motion changes of the tangential problem (the
// pressure, the reference point, the rigid slip from the kinematics); summed over the wheel's areas.
#include "area.hpp"
#include "tangential_step.hpp"

#include "wrc/core/error.hpp"

#include <Eigen/Geometry>

#include <cmath>

namespace wrc {
namespace {

Jacobian area_jacobian(const ContactModel& model, const Pose& pose, const PatchContact& pc,
                       const std::optional<RollingRequest>& rolling, ContactWorkspace& ws) {
  Jacobian J = Jacobian::Zero();
  if (!(pc.solution.force > 0)) return J;
  std::array<areas::NormalColumn, 4> normal;
  std::array<Eigen::Vector2d, 4> dref;
  for (int c = 0; c < 4; ++c) {
    normal[static_cast<std::size_t>(c)] = areas::normal_column(model, pose, pc, c, ws, kJacobianSolveTolerance);
    J.block<3, 1>(0, kJacobianPose + c) = normal[static_cast<std::size_t>(c)].dF;
    J.block<3, 1>(3, kJacobianPose + c) = normal[static_cast<std::size_t>(c)].dM;
    dref[static_cast<std::size_t>(c)] = normal[static_cast<std::size_t>(c)].dref;
  }
  if (rolling && pc.rolling) J += rolling_jacobian(model, pose, pc, *rolling, normal, dref, ws);
  return J;
}

}  // namespace

void add_jacobian(const ContactModel& model, ContactResult& result, const std::optional<RollingRequest>& rolling,
                  ContactWorkspace& ws) {
  static_assert(areas::kPoseY == 0 && areas::kPoseYaw == 3, "the Jacobian's pose columns follow PoseCoordinate");
  for (WheelContact& wc : result.wheel) {
    Jacobian J = Jacobian::Zero();
    for (const PatchContact& pc : wc.patches) {
      areas::PhaseTimer t(ws, ws.times.sensitivity);
      J += area_jacobian(model, result.pose, pc, rolling, ws);
    }
    wc.jacobian = J;
  }
}

Jacobian constant_fz(const Jacobian& J) {
  const int z = kJacobianPose + areas::kPoseZ;
  const double k = J(2, z);  // dFz/dz < 0: the wheel pressed down carries more
  if (!(k < 0))
    fail("contact sensitivity: dFz/dz = {} N/m: the wheel has no vertical stiffness to hold its load with", k);
  Jacobian out = J;
  for (int c = 0; c < 7; ++c)
    if (c != z) out.col(c) -= J.col(z) * (J(2, c) / k);
  out.col(z) = J.col(z) / k;
  return out;
}

void describe_jacobian(const char* name, const Jacobian& J, bool fz, FieldSink& out) {
  out.begin(name, {"", fz ? "derivatives of the wheel's (Fx, Fy, Fz, Mx, My, Mz) with its Fz held (z adjusting); column "
                            "z: by Fz (per N) (with sensitivity)"
                          : "derivatives of the wheel's (Fx, Fy, Fz, Mx, My, Mz) (track frame, moments about the "
                            "wheelset centre) by the creepages and the pose (with sensitivity)"});
  static constexpr const char* kUnits[7] = {"N, N m per unit", "N, N m per unit", "N m, N m^2", "N/m, N m/m",
                                            "N/m, N m/m", "N/rad, N m/rad", "N/rad, N m/rad"};
  static constexpr const char* kWhat[7] = {"by the longitudinal creepage xi", "by the lateral creepage eta",
                                           "by the spin creepage phi (1/m)", "by the lateral position y",
                                           "by the height z", "by the roll", "by the yaw"};
  for (int c = 0; c < 7; ++c) {
    const double v[6] = {J(0, c), J(1, c), J(2, c), J(3, c), J(4, c), J(5, c)};
    const bool by_fz = fz && c == kJacobianPose + areas::kPoseZ;
    out.numbers(kJacobianColumns[c], v, 6,
                {by_fz ? "-, m" : kUnits[c], by_fz ? "by the vertical force Fz (per N)" : kWhat[c]});
  }
  out.end();
}

}  // namespace wrc
