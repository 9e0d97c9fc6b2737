// `#SBATCH` lines that sbatch reads back as exactly the values given, whatever they hold. The
// only writer of such lines: every value of a batch script's header goes through it.
//
// sbatch parses these lines itself, not the shell (Slurm 22.05, src/sbatch/opt.c): a word ends
// at white space outside quotes, '"' and '\'' quote, '\\' takes the next character literally
// (inside quotes too), an unquoted '#' starts a comment, a word may not start with ':', and a
// line holding "hetjob" or "packjob" (any case) has that word overwritten with spaces. A line
// break ends the line whatever precedes it: no value can carry one.
#pragma once

#include <string>

namespace taa::farm {

// "#SBATCH --name=\"value\"\n": `name` is a long option ("--partition"), `value` anything but a
// line break or NUL. Throws UsageError naming `what` (the taa-farm option or folder the value
// came from) when the value cannot be written or the name is not an option name.
std::string sbatchLine(const std::string& name, const std::string& value, const std::string& what);

// A line of a --sbatch-arg: one sbatch option as a user writes it on sbatch's command line,
// "--qos=high", "--exclusive" or "-p debug"; its value quoted as above. Throws UsageError
// for anything else.
std::string sbatchLineOf(const std::string& optionText);

}  // namespace taa::farm
