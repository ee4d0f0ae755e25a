package io.github.jdem846.cli;

import java.util.Arrays;
import java.util.stream.Collectors;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.ParameterException;

/**
 * Usage errors as picocli {@link ParameterException}s, which {@link CliExceptionHandler} prints as one line with a
 * hint and exit status 2. The ranges themselves are checked by the library classes the options feed; this turns
 * their {@link IllegalArgumentException} into a usage error that names the option.
 */
final class Usage {

    private Usage() {
    }

    /** Runs {@code check} (a library check of one value); its IllegalArgumentException becomes a usage error. */
    static void check(CommandSpec spec, String option, Runnable check) {
        try {
            check.run();
        } catch (IllegalArgumentException e) {
            throw invalid(spec, e.getMessage(), option);
        }
    }

    /** "Invalid value for option '--x': {@code problem}" (or "for options '--x' and '--y'"). */
    static ParameterException invalid(CommandSpec spec, String problem, String... options) {
        String names = Arrays.stream(options).map(o -> "'" + o + "'").collect(Collectors.joining(" and "));
        return new ParameterException(spec.commandLine(), "Invalid value for option" + (options.length > 1 ? "s "
                : " ") + names + ": " + problem);
    }

    /** A usage error that is not about one value, e.g. two options that exclude each other. */
    static ParameterException error(CommandSpec spec, String message) {
        return new ParameterException(spec.commandLine(), message);
    }
}
