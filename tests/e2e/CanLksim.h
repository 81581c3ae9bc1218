#pragma once

#include "LksimProcess.h"

#include <QtCore/QString>
#include <QtCore/QStringList>
#include <QtNetwork/QTcpServer>

#include <memory>

namespace lk::e2e {

/// A TCP port nobody uses now: Qt's virtualcan server is system-wide, so each test (and each
/// parallel ctest run) takes a port of its own and never hears another's frames.
inline quint16 freeCanPort()
{
    QTcpServer s;
    s.listen(QHostAddress::LocalHost, 0);
    return s.serverPort();
}

#ifdef LKSIM_PATH
/// lksim --can on a virtualcan bus of its own port: what every lkctl-on-CAN test starts from.
/// lksim holds the virtualcan server of the port; lkctl joins it with can().
class CanLksim {
public:
    /// Starts lksim with `motors` ("1:MG@can,2:MF@can236") and `extra` arguments; empty, or
    /// what failed.
    QString start(const QString &motors, const QStringList &extra = {})
    {
        m_url = QStringLiteral("virtualcan:tcp://127.0.0.1:%1/can0").arg(freeCanPort());
        m_sim = std::make_unique<LksimProcess>(QStringLiteral(LKSIM_PATH));
        if (!m_sim->start(
                QStringList{QStringLiteral("--can"), m_url, QStringLiteral("--motors"), motors} +
                extra))
            return m_sim->errorString();
        return {};
    }
    void stop() { m_sim.reset(); }
    bool isRunning() const { return m_sim != nullptr; }
    LksimProcess *process() const { return m_sim.get(); }
    /// "virtualcan:tcp://127.0.0.1:PORT/can0", as --can takes it.
    QString url() const { return m_url; }
    /// --can URL, to append to an lkctl command line.
    QStringList can() const { return {QStringLiteral("--can"), m_url}; }

private:
    std::unique_ptr<LksimProcess> m_sim;
    QString m_url;
};
#endif

} // namespace lk::e2e
