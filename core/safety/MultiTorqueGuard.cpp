#include "MultiTorqueGuard.h"

#include <algorithm>

#include <QtCore/QCoreApplication>
#include <QtCore/QSet>

#include <cmath>
#include <variant>

namespace lk::safety {

namespace {
MultiTorqueVerdict problem(MultiTorqueProblem p, int id = 0)
{
    MultiTorqueVerdict v;
    v.problem = p;
    v.id = id;
    return v;
}

/// The frame as a whole, before any drive's limits.
MultiTorqueVerdict checkShape(const QVector<protocol::Request> &torques, protocol::Link link)
{
    if (torques.isEmpty())
        return problem(MultiTorqueProblem::NoDrive);
    if (torques.size() > MultiTorqueGuard::kMaxDrives)
        return problem(MultiTorqueProblem::TooManyDrives);
    if (link != protocol::Link::Can)
        return problem(MultiTorqueProblem::NotCan);
    QSet<int> seen;
    for (const protocol::Request &r : torques) {
        if (r.command != protocol::Command::Torque ||
            !std::holds_alternative<protocol::TorqueCommand>(r.payload))
            return problem(MultiTorqueProblem::NotTorque, r.id);
        if (r.id < 1 || r.id > MultiTorqueGuard::kMaxDrives)
            return problem(MultiTorqueProblem::IdOutOfRange, r.id);
        if (seen.contains(r.id))
            return problem(MultiTorqueProblem::DuplicateId, r.id);
        seen.insert(r.id);
    }
    return {};
}
} // namespace

MultiTorqueVerdict MultiTorqueGuard::check(const QVector<protocol::Request> &torques,
                                           protocol::Link link, const DriveLookup &drive,
                                           const QSet<int> &onBus)
{
    const MultiTorqueVerdict shape = checkShape(torques, link);
    if (!shape.allowed())
        return shape;
    for (const protocol::Request &r : torques) {
        const MultiTorqueDrive d = drive(r.id);
        if (!d.generation)
            return problem(MultiTorqueProblem::UnknownGeneration, r.id);
        if (*d.generation != protocol::Generation::V2_3)
            return problem(MultiTorqueProblem::V236, r.id);
        // The same gate as one torque command: series known, its current, the torque limit.
        const Verdict v = MotionGuard::check(r, d.series, d.limits);
        if (!v.allowed()) {
            MultiTorqueVerdict out = problem(MultiTorqueProblem::Limit, r.id);
            out.verdict = v;
            return out;
        }
    }
    // After the named drives' own refusals, which say more about what was asked.
    for (int id = 1; id <= kMaxDrives; ++id) {
        const bool named = std::any_of(torques.cbegin(), torques.cend(),
                                       [id](const protocol::Request &r) { return r.id == id; });
        if (!named && onBus.contains(id))
            return problem(MultiTorqueProblem::UnnamedDrive, id);
    }
    return {};
}

QString MultiTorqueGuard::text(const MultiTorqueVerdict &v)
{
    switch (v.problem) {
    case MultiTorqueProblem::None:
        return {};
    case MultiTorqueProblem::NoDrive:
        return QCoreApplication::translate(
            "lk::safety::MultiTorqueGuard",
            "the multi-motor torque frame names no drive; nothing was sent");
    case MultiTorqueProblem::TooManyDrives:
        return QCoreApplication::translate(
            "lk::safety::MultiTorqueGuard",
            "the multi-motor torque frame carries at most 4 drives (IDs 1..4); nothing "
            "was sent");
    case MultiTorqueProblem::IdOutOfRange:
        return QCoreApplication::translate(
                   "lk::safety::MultiTorqueGuard",
                   "drive %1: the multi-motor torque frame (0x280) has slots for IDs 1..4 only; "
                   "nothing was sent")
            .arg(v.id);
    case MultiTorqueProblem::DuplicateId:
        return QCoreApplication::translate("lk::safety::MultiTorqueGuard",
                                           "drive %1 is named twice; nothing was sent")
            .arg(v.id);
    case MultiTorqueProblem::NotTorque:
        return QCoreApplication::translate(
                   "lk::safety::MultiTorqueGuard",
                   "drive %1: only torque goes in a multi-motor frame; nothing was sent")
            .arg(v.id);
    case MultiTorqueProblem::UnnamedDrive:
        return QCoreApplication::translate(
                   "lk::safety::MultiTorqueGuard",
                   "drive %1 is on the bus and would get 0 A from the multi-motor torque frame, "
                   "which has a slot for each of IDs 1..4: name it (%1=0 for zero torque on "
                   "purpose); nothing was sent")
            .arg(v.id);
    case MultiTorqueProblem::NotCan:
        return QCoreApplication::translate(
            "lk::safety::MultiTorqueGuard",
            "the multi-motor torque frame (0x280) exists on CAN only (the old CAN "
            "generation); RS485 has none; nothing was sent");
    case MultiTorqueProblem::UnknownGeneration:
        return QCoreApplication::translate(
                   "lk::safety::MultiTorqueGuard",
                   "drive %1: its series and CAN generation are not known (give them, e.g. "
                   "--drives %1:MG@can); the multi-motor frame exists on the old generation only; "
                   "nothing was sent")
            .arg(v.id);
    case MultiTorqueProblem::V236:
        return QCoreApplication::translate(
                   "lk::safety::MultiTorqueGuard",
                   "drive %1 speaks CAN V2.36, whose documents have no multi-motor torque frame "
                   "(0x280 is encoded for the old generation only); nothing was sent")
            .arg(v.id);
    case MultiTorqueProblem::Limit:
        break;
    }
    const Verdict &l = v.verdict;
    switch (l.kind) {
    case LimitKind::UnknownSeries:
        return QCoreApplication::translate(
                   "lk::safety::MultiTorqueGuard",
                   "drive %1: its series is not known, so its torque cannot be bounded (give it, "
                   "e.g. --drives %1:MG@can); nothing was sent")
            .arg(v.id);
    case LimitKind::SeriesCurrent:
        return QCoreApplication::translate(
                   "lk::safety::MultiTorqueGuard",
                   "drive %1: |iq| %2 A is over its series' current %3 A; nothing was sent")
            .arg(v.id)
            .arg(l.value)
            .arg(l.limit);
    case LimitKind::SoftTorque:
        return QCoreApplication::translate(
                   "lk::safety::MultiTorqueGuard",
                   "drive %1: |iq| %2 A is over its torque limit %3 A (max_torque_a); nothing was "
                   "sent")
            .arg(v.id)
            .arg(l.value)
            .arg(l.limit);
    case LimitKind::Unsupported:
        return QCoreApplication::translate(
                   "lk::safety::MultiTorqueGuard",
                   "drive %1: its series has no torque command; nothing was sent")
            .arg(v.id);
    default:
        return QCoreApplication::translate("lk::safety::MultiTorqueGuard",
                                           "drive %1: refused by its limits; nothing was sent")
            .arg(v.id);
    }
}

} // namespace lk::safety
