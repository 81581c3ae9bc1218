#include "LeaveGuard.h"

#include "BusController.h"
#include "CommandedMotion.h"

#include <panels/BusModel.h>

#include <bus/BusSession.h>
#include <protocol/RequestBuilder.h>

#include <QtCore/QEventLoop>
#include <QtCore/QLoggingCategory>
#include <QtCore/QTimer>
#include <QtWidgets/QMessageBox>
#include <QtWidgets/QPushButton>

#include <algorithm>

Q_LOGGING_CATEGORY(lcLeave, "lk.studio.leave")

namespace lk::ui {

LeaveGuard::LeaveGuard(BusController *controller, CommandedMotion *motion, QWidget *dialogParent,
                       QObject *parent)
    : QObject(parent), m_controller(controller), m_motion(motion), m_dialogParent(dialogParent)
{
}

QString LeaveGuard::idList(const QVector<int> &ids)
{
    QStringList parts;
    for (int id : ids)
        parts << QString::number(id);
    return parts.join(QStringLiteral(", "));
}

bool LeaveGuard::prepare(Leaving why)
{
    const QVector<int> ids = m_motion->movingIds();
    if (ids.isEmpty())
        return true;
    const bool canSend = m_controller->model()->canSend();
    Choice choice = Choice::Stop;
    if (why != Leaving::Signal && !m_demo)
        choice = ask(why, ids);
    else if (!canSend)
        choice = Choice::LeaveRunning; // nothing can be sent: say so, do not wait
    switch (choice) {
    case Choice::Stay:
        qCInfo(lcLeave).noquote() << "stayed: drive(s)" << idList(ids) << "keep moving";
        return false;
    case Choice::LeaveRunning: {
        QStringList what;
        for (int id : ids)
            what << m_motion->driveText(id);
        m_report = (canSend ? tr("Left running at the user's choice: %1.")
                            : tr("Not stopped, the bus is not connected: %1 may still be moving."))
                       .arg(what.join(QStringLiteral("; ")));
        qCWarning(lcLeave).noquote() << m_report;
        return true;
    }
    case Choice::Stop: {
        const bool demo = m_demo; // the demo ends as its drives acknowledge
        report(ids, stopAndWait(ids), demo);
        return true;
    }
    }
    return true;
}

LeaveGuard::Choice LeaveGuard::ask(Leaving why, const QVector<int> &ids) const
{
    const bool quit = why == Leaving::Quit;
    const int n = int(ids.size());
    QStringList commanded;
    for (int id : ids)
        commanded << m_motion->driveText(id);
    QMessageBox box(m_dialogParent);
    box.setObjectName(QStringLiteral("leaveGuardDialog"));
    box.setIcon(QMessageBox::Warning);
    box.setWindowTitle(quit ? tr("Quit") : tr("Disconnect"));
    if (!m_controller->model()->canSend()) {
        const QString what = n == 1 ? tr("Drive %1 may still be moving").arg(idList(ids))
                                    : tr("Drives %1 may still be moving").arg(idList(ids));
        box.setText(quit ? tr("%1 and the bus is not connected: quit anyway?").arg(what)
                         : tr("%1 and the bus is not connected: disconnect anyway?").arg(what));
        box.setInformativeText(tr("Commanded to move: %1. Nothing can be sent to stop them now; "
                                  "they keep their last command until their input-timeout "
                                  "protection (if set) stops them.")
                                   .arg(commanded.join(QStringLiteral("; "))));
        QPushButton *leave = box.addButton(quit ? tr("Quit anyway") : tr("Disconnect anyway"),
                                           QMessageBox::DestructiveRole);
        box.setDefaultButton(box.addButton(QMessageBox::Cancel));
        box.exec();
        return box.clickedButton() == leave ? Choice::LeaveRunning : Choice::Stay;
    }
    const QString question = quit ? (n == 1 ? tr("Stop drive %1 before quitting?")
                                            : tr("Stop drives %1 before quitting?"))
                                  : (n == 1 ? tr("Stop drive %1 before disconnecting?")
                                            : tr("Stop drives %1 before disconnecting?"));
    box.setText(question.arg(idList(ids)));
    box.setInformativeText(tr("Commanded to move on this connection: %1. Left running, they keep "
                              "their last command after lkstudio has let go of the bus; they stop "
                              "by themselves only if their input-timeout protection is set.")
                               .arg(commanded.join(QStringLiteral("; "))));
    QPushButton *stop = box.addButton(quit ? tr("Stop and quit") : tr("Stop and disconnect"),
                                      QMessageBox::AcceptRole);
    stop->setObjectName(QStringLiteral("stopAndLeave"));
    QPushButton *leave = box.addButton(tr("Leave running"), QMessageBox::DestructiveRole);
    leave->setObjectName(QStringLiteral("leaveRunning"));
    box.addButton(QMessageBox::Cancel);
    box.setDefaultButton(stop);
    box.exec();
    if (box.clickedButton() == stop)
        return Choice::Stop;
    return box.clickedButton() == leave ? Choice::LeaveRunning : Choice::Stay;
}

QVector<int> LeaveGuard::stopAndWait(const QVector<int> &ids)
{
    QVector<int> acknowledged;
    int ended = 0;
    QEventLoop loop; // the context of the callbacks: ends that come later are dropped with it
    for (int id : ids) {
        const auto built = protocol::build::plain(protocol::Command::MotorOff, id);
        m_controller->session()->send(
            *built.request, &loop,
            [&](const bus::RequestResult &r) {
                if (r.ok())
                    acknowledged.append(r.request.id);
                if (++ended == ids.size())
                    loop.quit();
            },
            bus::Priority::Emergency);
    }
    QTimer::singleShot(kStopWaitMs, &loop, &QEventLoop::quit);
    loop.exec(); // every end comes through the event loop, never inside send()
    std::sort(acknowledged.begin(), acknowledged.end());
    return acknowledged;
}

void LeaveGuard::report(const QVector<int> &ids, const QVector<int> &acknowledged, bool demo)
{
    QVector<int> missing;
    for (int id : ids) {
        if (!acknowledged.contains(id))
            missing.append(id);
    }
    QStringList parts;
    if (demo)
        parts << tr("The demo's simulated drives were stopped.");
    if (!acknowledged.isEmpty())
        parts << (acknowledged.size() == 1 ? tr("Motor Off (0x80) acknowledged by drive %1.")
                                           : tr("Motor Off (0x80) acknowledged by drives %1."))
                     .arg(idList(acknowledged));
    for (int id : missing)
        parts << tr("%1 did not acknowledge Motor Off: it may still be moving.")
                     .arg(m_motion->driveText(id));
    m_report = parts.join(QLatin1Char(' '));
    if (missing.isEmpty())
        qCInfo(lcLeave).noquote() << m_report;
    else
        qCWarning(lcLeave).noquote() << m_report;
    emit stopReported(m_report, missing.isEmpty());
}

} // namespace lk::ui
