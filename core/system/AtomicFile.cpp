#include "AtomicFile.h"

#include <QtCore/QCoreApplication>

namespace lk::system {

AtomicFile::AtomicFile(const QString &path) : m_file(path) {}

AtomicFile::~AtomicFile()
{
    if (m_open)
        m_file.cancelWriting(); // never leave a half file behind
}

bool AtomicFile::open()
{
    m_error.clear();
    m_open = m_file.open(QIODevice::WriteOnly);
    if (!m_open)
        m_error = m_file.errorString();
    return m_open;
}

bool AtomicFile::write(const QByteArray &bytes)
{
    if (!m_open || !m_error.isEmpty())
        return false;
    if (m_file.write(bytes) == bytes.size())
        return true;
    fail(m_file.errorString());
    return false;
}

void AtomicFile::fail(const QString &why)
{
    if (m_error.isEmpty())
        m_error = why; // the first error is the cause; later ones are consequences
}

bool AtomicFile::commit()
{
    if (!m_open) {
        if (m_error.isEmpty())
            m_error =
                QCoreApplication::translate("lk::system::AtomicFile", "the file was not opened");
        return false;
    }
    m_open = false;
    // The flush before commit(): a failure here still cancels, one inside commit() would not.
    if (m_error.isEmpty() && !m_file.flush())
        fail(m_file.errorString());
    if (!m_error.isEmpty()) {
        m_file.cancelWriting();
        return false;
    }
    if (!m_file.commit()) {
        fail(m_file.errorString());
        return false;
    }
    return true;
}

QString AtomicFile::writeAll(const QString &path, const QByteArray &bytes)
{
    AtomicFile file(path);
    if (file.open() && file.write(bytes) && file.commit())
        return {};
    return file.errorString();
}

} // namespace lk::system
