package io.github.jdem846.cli;

import io.github.jdem846.output.OutputOverwritesInputException;
import java.io.PrintWriter;
import picocli.CommandLine;

/**
 * Turns an exception from a subcommand into one line for a person: {@code jdem846: <message>} and exit status 1,
 * or 2 for bad usage (a parameter error, an output that would overwrite an input).
 * The stack trace is printed only with {@code --verbose} (any subcommand that has a {@link VerboseOption} mixin).
 */
final class CliExceptionHandler implements CommandLine.IExecutionExceptionHandler {

    @Override
    public int handleExecutionException(Exception ex, CommandLine commandLine,
                                        CommandLine.ParseResult parseResult) {
        PrintWriter err = commandLine.getErr();
        if (ex instanceof CommandLine.ParameterException pe) {
            err.println("jdem846: " + pe.getMessage());
            return 2;
        }
        if (ex instanceof OutputOverwritesInputException overwrite) {
            err.println("jdem846: " + overwrite.getMessage());
            err.flush();
            return 2;
        }
        String message = ex.getMessage();
        if (message == null || message.isBlank()) {
            message = ex.getClass().getSimpleName();
        }
        err.println("jdem846: " + message);
        if (isVerbose(parseResult)) {
            ex.printStackTrace(err);
        }
        err.flush();
        return 1;
    }

    private static boolean isVerbose(CommandLine.ParseResult parseResult) {
        for (CommandLine.ParseResult pr = parseResult; pr != null; pr = pr.subcommand()) {
            if (pr.hasMatchedOption("--verbose")) {
                return true;
            }
        }
        return false;
    }
}
