package io.github.jdem846.cli;

import java.util.Arrays;
import java.util.stream.Collectors;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.ParameterException;

/**
 * Usage errors as picocli {@link ParameterException}s, which {@link CliExceptionHandler} prints as one line with a
 * hint and exit status 2: options that exclude each other, and values that turn out not to fit the grid once its
 * header is read. (A value out of its own range is refused while parsing, by {@link Converters}.)
 */
final class Usage {

    private Usage() {
    }

    /** Runs {@code check} (a library check); its IllegalArgumentException becomes a usage error about {@code option}. */
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
