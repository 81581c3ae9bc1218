#include "TuningText.h"

namespace lk::ui {

QString TuningText::gains(const protocol::PidGains &p)
{
    return QStringLiteral("%1/%2, %3/%4, %5/%6")
        .arg(p.angleKp)
        .arg(p.angleKi)
        .arg(p.speedKp)
        .arg(p.speedKi)
        .arg(p.iqKp)
        .arg(p.iqKi);
}

QString TuningText::time(const QTime &t)
{
    return t.toString(QStringLiteral("HH:mm:ss"));
}

ConfirmRequest TuningText::romWrite(int id, const protocol::PidGains &pid)
{
    ConfirmRequest q;
    q.key = QStringLiteral("write_pid_rom");
    q.title = tr("Write gains to ROM");
    q.question = tr("Write these PID gains to the ROM of drive %1?\n%2 (angle, speed, iq Kp/Ki)")
                     .arg(id)
                     .arg(gains(pid));
    q.reason = tr("ROM is the drive's flash memory: each write wears it, and the gains stay "
                  "after power-off. Try them in RAM first; write to ROM once you are satisfied. "
                  "Acceleration is written to RAM only (V2.3 has no ROM command for it). "
                  "Afterwards the gains are read back from RAM; V2.3 has no command that reads "
                  "ROM, so the ROM copy itself cannot be checked.");
    q.acceptText = tr("Write to ROM");
    return q;
}

ConfirmRequest TuningText::restore(int id, const QTime &readAt, const QString &values)
{
    ConfirmRequest q;
    q.key = QStringLiteral("restore_first_read");
    q.title = tr("Restore values read at %1").arg(time(readAt));
    q.question = tr("Write the values first read from drive %1 at %2 to its RAM now?\n%3")
                     .arg(id)
                     .arg(time(readAt))
                     .arg(values);
    q.reason = tr("This writes to the drive: the values in its RAM are replaced at once, and "
                  "so is your pending edit. ROM is not touched; RAM is lost at "
                  "power-off.");
    q.acceptText = tr("Write to RAM");
    return q;
}

QStringList TuningText::readBackProblems(const TuningWrite &sent,
                                         const std::optional<protocol::PidGains> &pid,
                                         const std::optional<qint32> &accelDps2, bool complete)
{
    QStringList problems;
    if (sent.pid && pid && *pid != *sent.pid) {
        if (sent.rom)
            problems << tr("RAM holds gains %1 after %2 was written to ROM: either the write did "
                           "not land or this drive takes ROM values into RAM only at power-on. "
                           "V2.3 cannot read ROM, so which of the two is not known.")
                            .arg(gains(*pid), gains(*sent.pid));
        else
            problems << tr("The drive holds gains %1 after %2 was written.")
                            .arg(gains(*pid), gains(*sent.pid));
    }
    if (sent.accelDps2 && accelDps2 && *accelDps2 != *sent.accelDps2)
        problems
            << tr("The drive reports acceleration %1 dps/s after %2 dps/s was written: "
                  "some firmware ignores 0x34 or reads 0 with 0x33 (see docs/ERRATA.md), so the "
                  "acceleration in effect is not known.")
                   .arg(*accelDps2)
                   .arg(*sent.accelDps2);
    if (!complete)
        problems << tr("The read-back did not complete: what the drive holds is not known. "
                       "Editing and writing stay off until Read from drive succeeds.");
    return problems;
}

QString TuningText::written(const TuningWrite &sent, int id)
{
    if (sent.rom)
        return tr("Written to the ROM of drive %1. Verified: the gains read back from RAM equal "
                  "what was sent. Not verifiable: this drive generation (V2.3) cannot read ROM; "
                  "the drive loads the ROM values at the next power-on, and only a read after "
                  "that shows them. Acceleration went to RAM only.")
            .arg(id);
    return tr("Written to the RAM of drive %1 and read back: the drive holds what was sent. Lost "
              "at power-off unless written to ROM.")
        .arg(id);
}

QString TuningText::can236RamOnly()
{
    return tr("CAN V2.36 keeps these in RAM only: they are lost at power-off. The drive has no "
              "command to store its control parameters (0xC0/0xC1) in ROM, so this view has no "
              "\"Write to ROM\" button.");
}

} // namespace lk::ui
