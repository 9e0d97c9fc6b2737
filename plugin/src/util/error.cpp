#include "taa/error.h"

TAA_NAMESPACE_BEGIN

std::string formatErrorMessage(const std::string& what, const ErrorContext& context) {
  std::string message = what;
  std::string where = context.file;
  std::string details;
  if (context.frame) details = "frame " + std::to_string(*context.frame);
  if (!context.channel.empty()) {
    if (!details.empty()) details += ", ";
    details += "channel " + context.channel;
  }
  if (!details.empty()) where += where.empty() ? details : " (" + details + ")";
  if (!where.empty()) message += " : " + where;
  return message;
}

Error::Error(const std::string& what, ErrorContext context)
    : std::runtime_error(formatErrorMessage(what, context)),
      description_(what),
      context_(std::move(context)) {}

TAA_NAMESPACE_END
