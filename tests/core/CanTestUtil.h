#pragma once

#include <protocol/CanLayout.h>
#include <protocol/Request.h>
#include <protocol/Series.h>

#include <QtCore/QByteArray>
#include <QtCore/QList>
#include <QtCore/QString>

// Shorthands of the CAN codec tests (tst_canlayout, tst_canframes): frames in candump notation.
namespace lk::test::cantest {

namespace proto = lk::protocol;
namespace can = lk::protocol::can;
using proto::Command;
using proto::DecodeContext;
using proto::Generation;
using proto::Link;
using proto::Series;

inline DecodeContext canCtx(Generation g, Series s = Series::MG)
{
    return DecodeContext{s, g, Link::Can};
}

/// "141#9C00000000000000" -> {0x141, bytes}.
inline can::CanData canFrame(const char *candump)
{
    const QList<QByteArray> parts = QByteArray(candump).split('#');
    return can::CanData{parts[0].toUInt(nullptr, 16), QByteArray::fromHex(parts[1])};
}

inline QString candump(const can::CanData &d)
{
    return QStringLiteral("%1#%2")
        .arg(d.canId, 3, 16)
        .arg(QString::fromLatin1(d.bytes.toHex()))
        .toUpper();
}

inline proto::Request req(Command c, proto::RequestPayload p = proto::NoPayload{})
{
    return proto::Request{c, 1, std::move(p)};
}

} // namespace lk::test::cantest
