// Gold's codes and texts for the preprocessor's errors (manual, compilation error table 86-97):
// the defaults a dialect gets when it does not give its own.
#include "preproc/preprocess.h"

namespace uprog::preproc {

int gold_code_of(PreprocError e) {
  switch (e) {
    case PreprocError::IdentifierMissing:
      return 87;
    case PreprocError::InvalidIdentifier:
      return 88;
    case PreprocError::AlreadyDefined:
      return 89;
    case PreprocError::ConditionMissing:
      return 90;
    case PreprocError::MisplacedElse:
      return 92;
    case PreprocError::NotDefined:
      return 93;
    case PreprocError::MismatchedType:
      return 94;
    case PreprocError::TooManyDefines:
      return 95;
    case PreprocError::MisplacedEndif:
      return 96;
    // The table has no code of its own for these; the nearest one names the broken pair.
    case PreprocError::UnterminatedIf:
      return 96;
    case PreprocError::TooManyElseifs:
      return 92;
    case PreprocError::UnknownDirective:
      return 97;
    case PreprocError::DivisionByZero:
      return 86;
    case PreprocError::ExpansionTooComplex:
      return 39;
    // Gold has no #include (allow_include is off): these cannot arise for it.
    case PreprocError::IncludeNotFound:
    case PreprocError::IncludeTooDeep:
      return 97;
  }
  return 97;
}

const char* gold_text_of(PreprocError e) {
  switch (gold_code_of(e)) {
    case 39:
      return "Code is too complex";
    case 86:
      return "Division by zero";
    case 87:
      return "Identifier is missing";
    case 88:
      return "The name of identifier is not valid";
    case 89:
      return "Identifier was defined before";
    case 90:
      return "Condition is missing";
    case 92:
      return "Misplaced #else or #elseif";
    case 93:
      return "Identifier wasn't declared";
    case 94:
      return "Mismatched type";
    case 95:
      return "Too many identifiers have been defined";
    case 96:
      return "Misplaced #endif";
    default:
      return "Unknown error";
  }
}

}  // namespace uprog::preproc
