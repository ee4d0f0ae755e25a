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
        CrsWarmUp.start();
        System.exit(commandLine().execute(args));
    }
}
