#include "HexText.h"

namespace lk::lkctl {

namespace {

bool isSeparator(char c)
{
    return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v' || c == ',' || c == ';' ||
           c == ':';
}

bool isHexDigit(char c)
{
    return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F');
}

bool endsGroup(char c)
{
    return isSeparator(c) || c == '\n' || c == '#';
}

QString describe(char c)
{
    const auto u = static_cast<unsigned char>(c);
    if (u >= 0x21 && u < 0x7F)
        return QStringLiteral("'%1'").arg(QLatin1Char(c));
    return QStringLiteral("byte 0x%1")
        .arg(u, 2, 16, QLatin1Char('0'))
        .toUpper()
        .replace(QLatin1String("0X"), QLatin1String("0x"));
}

/// Scans the text once; a group is the run of characters between separators.
class Scanner {
public:
    Scanner(const QByteArray &text, int firstLine) : m_text(text), m_line(firstLine) {}

    std::optional<QByteArray> run(HexError *error)
    {
        QByteArray out;
        out.reserve(m_text.size() / 2);
        while (m_pos < m_text.size()) {
            const char c = m_text.at(m_pos);
            if (c == '\n') {
                ++m_line;
                m_lineStart = ++m_pos;
            } else if (c == '#') {
                skipComment();
            } else if (isSeparator(c)) {
                ++m_pos;
            } else if (!group(out, error)) {
                return std::nullopt;
            }
        }
        return out;
    }

private:
    void skipComment()
    {
        while (m_pos < m_text.size() && m_text.at(m_pos) != '\n')
            ++m_pos;
    }

    bool fail(HexError *error, qsizetype at, const QString &problem) const
    {
        if (error)
            *error = HexError{m_line, int(at - m_lineStart + 1), problem};
        return false;
    }

    bool group(QByteArray &out, HexError *error)
    {
        const qsizetype start = m_pos;
        if (m_text.at(m_pos) == '0' && m_pos + 1 < m_text.size() &&
            (m_text.at(m_pos + 1) == 'x' || m_text.at(m_pos + 1) == 'X'))
            m_pos += 2;
        const qsizetype digits = m_pos;
        while (m_pos < m_text.size() && isHexDigit(m_text.at(m_pos)))
            ++m_pos;
        if (m_pos < m_text.size() && !endsGroup(m_text.at(m_pos)))
            return fail(error, m_pos,
                        QStringLiteral("%1 is not a hex digit").arg(describe(m_text.at(m_pos))));
        const qsizetype count = m_pos - digits;
        const QString text = QString::fromLatin1(m_text.mid(start, m_pos - start));
        if (count == 0)
            return fail(error, start, QStringLiteral("'%1' has no hex digits").arg(text));
        if (count % 2 != 0)
            return fail(error, start,
                        QStringLiteral("odd number of hex digits in '%1' (a byte is two digits)")
                            .arg(text));
        out.append(QByteArray::fromHex(m_text.mid(digits, count)));
        return true;
    }

    const QByteArray &m_text;
    qsizetype m_pos = 0;
    qsizetype m_lineStart = 0;
    int m_line;
};

} // namespace

std::optional<QByteArray> HexText::parse(const QByteArray &text, HexError *error, int firstLine)
{
    return Scanner(text, firstLine).run(error);
}

} // namespace lk::lkctl
