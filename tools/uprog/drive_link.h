// A host's connection to a drive of a known dialect, as `uprog term` and `uprog download` open
// it: the client counts answers where the dialect's drive marks no line ends, and an error
// without a text (a real drive sends only its code) is shown with the dialect's text for it.
#pragma once
#include <memory>
#include <string>

#include "dialect/dialect.h"
#include "transport/drive_client.h"

namespace uprog::cli {

std::unique_ptr<transport::DriveClient> connect_to_drive(const std::string& address,
                                                         const dialect::Dialect& d,
                                                         std::string& error);
// `?CODE TEXT` for an error answer.
std::string shown_error(const dialect::Dialect& d, const transport::Reply& reply);

}  // namespace uprog::cli
