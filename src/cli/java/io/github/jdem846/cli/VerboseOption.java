package io.github.jdem846.cli;

import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/** {@code --verbose}: print stack traces of failures and phase timings (mix into every subcommand). */
@Command(addMethodSubcommands = false) // no command methods to look for: a quicker start
public final class VerboseOption {
    @Option(names = "--verbose", description = "Print the full stack trace when something fails, and the time "
            + "each phase took (hillshade, tint, render).")
    boolean verbose;

    /** True when {@code --verbose} was given. */
    public boolean isVerbose() {
        return verbose;
    }
}
