#pragma once

#include <protocol/FieldError.h>
#include <protocol/ProtocolFields.h>
#include <protocol/Request.h>

#include <QtCore/QMap>
#include <QtCore/QString>

#include <optional>

namespace lk::lkctl {

/// Field values as typed by a user: CLI.md field name -> text ("id" included).
using FieldValues = QMap<QString, QString>;

/// Outcome of building a request from text fields.
struct FieldBuildResult {
    std::optional<protocol::Request> request;
    std::optional<protocol::FieldError> fieldError; ///< set when one field's value was refused
    QString message; ///< why it failed, one line naming the field and range
    bool ok() const { return request.has_value(); }
};

/// Text fields to a validated request (`lkctl encode`, `write`, `control`): the fields a
/// command takes and how each is written come from protocol::ProtocolFields, the ranges are
/// the builders' of protocol/RequestBuilder.h. Nothing is clamped; missing, unknown,
/// non-numeric and out-of-range fields are refused.
class RequestText {
public:
    /// `drive`: the series and generation of the drive the request is for, which give the
    /// torque command's scale (V2.35 MF and MG differ from V2.3). Without a drive (encode,
    /// write) the V2.3 scale applies; `lkctl control` passes the drive it identified.
    static FieldBuildResult build(protocol::Command command, const FieldValues &values,
                                  const protocol::DecodeContext &drive = {});
    static FieldBuildResult build(const QString &commandName, const FieldValues &values,
                                  const protocol::DecodeContext &drive = {});
};

} // namespace lk::lkctl
