#pragma once

#include <QtCore/QByteArray>
#include <QtCore/QtEndian>

namespace lk::protocol {

/// Little-endian field writer/reader for frame data; every read is bounds-checked by the
/// callers' length validation, so a short frame is never read as zeros.
class WireWriter {
public:
    explicit WireWriter(qsizetype reserve = 16) { m_bytes.reserve(reserve); }
    template <typename T> WireWriter &put(T v)
    {
        char b[sizeof(T)];
        qToLittleEndian(v, b);
        m_bytes.append(b, sizeof(T));
        return *this;
    }
    WireWriter &putBytes(const QByteArray &b)
    {
        m_bytes.append(b);
        return *this;
    }
    QByteArray bytes() const { return m_bytes; }

private:
    QByteArray m_bytes;
};

/// Reads little-endian fields from frame data at fixed offsets.
class WireReader {
public:
    explicit WireReader(const QByteArray &bytes) : m_bytes(bytes) {}
    template <typename T> T get(qsizetype offset) const
    {
        Q_ASSERT(offset + qsizetype(sizeof(T)) <= m_bytes.size());
        return qFromLittleEndian<T>(m_bytes.constData() + offset);
    }
    const QByteArray &bytes() const { return m_bytes; }

private:
    const QByteArray &m_bytes;
};

} // namespace lk::protocol
