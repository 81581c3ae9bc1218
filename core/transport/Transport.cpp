#include "Transport.h"

#include <QtCore/QDebug>

namespace lk::transport {

bool Transport::refuseWriteIfReadOnly(const QByteArray &bytes)
{
    if (!m_readOnly)
        return false;
    // The bus refuses every send in listen-only mode before it reaches a transport: bytes here
    // mean a path that forgot to ask. They are dropped, never put on a bus another master owns.
    m_refusedWrites += static_cast<quint64>(bytes.size());
    qWarning().noquote() << QStringLiteral("%1: read-only (listen-only), %2 byte(s) not sent")
                                .arg(description())
                                .arg(bytes.size());
    return true;
}

} // namespace lk::transport
