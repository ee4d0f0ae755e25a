package io.github.jdem846.cli;

import io.github.jdem846.job.InsufficientHeapException;
import io.github.jdem846.output.OutputOverwritesInputException;
import java.io.PrintWriter;
import java.util.List;
import picocli.CommandLine;

/**
 * Turns what goes wrong into one line for a person. Bad usage (a {@link CommandLine.ParameterException}: an unknown
 * option, a missing or malformed value, a value out of its range) prints {@code jdem846: <message>} and a hint to
 * {@code --help}, exit status 2, never the usage text. An exception from a subcommand prints
 * {@code jdem846: <message>}, exit status 1; its stack trace only with {@code --verbose} (any subcommand that has a
 * {@link VerboseOption} mixin). An output that would overwrite an input ({@link OutputOverwritesInputException})
 * is bad usage too: one line, exit status 2.
 */
final class CliExceptionHandler implements CommandLine.IExecutionExceptionHandler,
        CommandLine.IParameterExceptionHandler {

    /** At most this many "did you mean" suggestions. */
    private static final int SUGGESTIONS = 3;

    @Override
    public int handleParseException(CommandLine.ParameterException ex, String[] args) {
        CommandLine cl = ex.getCommandLine();
        PrintWriter err = cl.getErr();
        err.println("jdem846: " + ex.getMessage());
        String hint = "Try '" + cl.getCommandSpec().qualifiedName() + " --help'.";
        if (ex instanceof CommandLine.UnmatchedArgumentException unmatched) {
            List<String> suggestions = unmatched.getSuggestions();
            if (!suggestions.isEmpty()) {
                hint = "Did you mean " + String.join(" or ", suggestions.subList(0,
                        Math.min(SUGGESTIONS, suggestions.size()))) + "? " + hint;
            }
        }
        err.println(hint);
        err.flush();
        return cl.getCommandSpec().exitCodeOnInvalidInput();
    }

    @Override
    public int handleExecutionException(Exception ex, CommandLine commandLine,
                                        CommandLine.ParseResult parseResult) {
        PrintWriter err = commandLine.getErr();
        if (ex instanceof OutputOverwritesInputException overwrite) {
            err.println("jdem846: " + overwrite.getMessage());
            err.flush();
            return 2;
        }
        String message = ex.getMessage();
        if (message == null || message.isBlank()) {
            message = ex.getClass().getSimpleName();
        }
        if (ex instanceof InsufficientHeapException heap && !heap.givesAdvice()) {
            message += "; " + Main.HEAP_ADVICE;
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
