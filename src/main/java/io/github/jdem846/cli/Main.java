package io.github.jdem846.cli;

import picocli.CommandLine;
import picocli.CommandLine.Command;

/**
 * The {@code jdem846} command line: a thin picocli front end over the library. Exit status 0 on success, 1 when an
 * input or the work fails, 2 on bad usage.
 */
@Command(name = "jdem846",
        mixinStandardHelpOptions = true,
        versionProvider = VersionProvider.class,
        description = "Shaded relief from digital elevation models: hypsometric tint, hillshade and ray-traced "
                + "cast shadows (a modern port of Kevin M. Gill's jDem846).",
        subcommands = {
            CommandLine.HelpCommand.class,
            RenderCommand.class,
            HillshadeCommand.class,
            TintCommand.class,
            ShadowsCommand.class,
            InfoCommand.class,
            SunCommand.class,
        })
public final class Main implements Runnable {

    @CommandLine.Spec
    CommandLine.Model.CommandSpec spec;

    @Override
    public void run() {
        throw new CommandLine.ParameterException(spec.commandLine(), "Missing a subcommand, e.g. 'jdem846 render'.");
    }

    /** Builds the configured command line (shared by {@link #main} and the tests). */
    public static CommandLine commandLine() {
        CommandLine cl = new CommandLine(new Main());
        cl.setExecutionExceptionHandler(new CliExceptionHandler());
        cl.setCaseInsensitiveEnumValuesAllowed(true);
        return cl;
    }

    public static void main(String[] args) {
        if (!java.util.Arrays.asList(args).contains("--verbose")) {
            quietLibraryLogs();
        }
        CrsWarmUp.start();
        System.exit(commandLine().execute(args));
    }

    /**
     * Apache SIS reports through java.util.logging (e.g. "SIS_DATA is not set", WKT elements it ignores); what
     * matters of that reaches the user as our own notices, so the CLI shows SIS's records only with --verbose.
     * Done through the LogManager's configuration, which also holds for loggers created later.
     */
    private static void quietLibraryLogs() {
        try {
            java.util.logging.LogManager.getLogManager().updateConfiguration(
                    new java.io.ByteArrayInputStream("org.apache.sis.level = OFF\n".getBytes(
                            java.nio.charset.StandardCharsets.ISO_8859_1)),
                    key -> (old, now) -> now != null ? now : old);
        } catch (java.io.IOException e) {
            // keep the default configuration
        }
    }
}
