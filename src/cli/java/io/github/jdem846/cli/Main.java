package io.github.jdem846.cli;

import java.util.List;
import java.util.Map;
import java.util.function.Supplier;
import picocli.CommandLine;
import picocli.CommandLine.Command;

/**
 * The {@code jdem846} command line: a thin picocli front end over the library. Exit status 0 on success, 1 when an
 * input or the work fails, 2 on bad usage.
 */
@Command(name = "jdem846", addMethodSubcommands = false,
        mixinStandardHelpOptions = true,
        versionProvider = VersionProvider.class,
        description = "Shaded relief from digital elevation models: hypsometric tint, hillshade and ray-traced "
                + "cast shadows (a modern port of Kevin M. Gill's jDem846).")
public final class Main implements Runnable {

    @CommandLine.Spec
    CommandLine.Model.CommandSpec spec;

    @Override
    public void run() {
        throw new CommandLine.ParameterException(spec.commandLine(), "Missing a subcommand, e.g. 'jdem846 render'.");
    }

    /** The subcommands, in the order {@code --help} lists them. */
    private static final List<Map.Entry<String, Supplier<Object>>> SUBCOMMANDS = List.of(
            Map.entry("help", CommandLine.HelpCommand::new),
            Map.entry("render", RenderCommand::new),
            Map.entry("view", ViewCommand::new),
            Map.entry("hillshade", HillshadeCommand::new),
            Map.entry("tint", TintCommand::new),
            Map.entry("shadows", ShadowsCommand::new),
            Map.entry("skyview", SkyViewCommand::new),
            Map.entry("tiles", TilesCommand::new),
            Map.entry("info", InfoCommand::new),
            Map.entry("sun", SunCommand::new),
            Map.entry("completion", picocli.AutoComplete.GenerateCompletion::new));

    /** Builds the configured command line with every subcommand (for help and the tests). */
    public static CommandLine commandLine() {
        return commandLine(new String[0]);
    }

    /**
     * Builds the command line for these arguments. When they start with the name of a subcommand other than
     * {@code help}, only that subcommand's model is built: picocli reads every command's options by reflection,
     * which is a noticeable part of a one-shot command's start-up (docs/performance.md, "Start-up and class-data
     * sharing"). Anything else (no arguments, an option, {@code help}, {@code completion}, which writes a script
     * for every command, an unknown name) gets all of them, so help and error messages are unchanged.
     */
    public static CommandLine commandLine(String[] args) {
        CommandLine cl = new CommandLine(new Main());
        String first = args.length > 0 ? args[0] : "";
        boolean known = SUBCOMMANDS.stream().anyMatch(e -> e.getKey().equals(first))
                && !first.equals("help") && !first.equals("completion");
        for (Map.Entry<String, Supplier<Object>> e : SUBCOMMANDS) {
            if (!known || e.getKey().equals(first)) {
                // a CommandLine of its own, so that picocli applies the command's model transformer
                // (GdaldemPositionals.Transformer), which it does when it builds a CommandLine
                cl.addSubcommand(e.getKey(), new CommandLine(e.getValue().get()));
            }
        }
        CliExceptionHandler handler = new CliExceptionHandler();
        cl.setExecutionExceptionHandler(handler);
        cl.setParameterExceptionHandler(handler);
        cl.setCaseInsensitiveEnumValuesAllowed(true);
        return cl;
    }

    public static void main(String[] args) {
        // picocli would look for Groovy on the class path (a failed class lookup) to support closures in annotations
        System.setProperty("picocli.disable.closures", "true");
        configureLibraryLogs(java.util.Arrays.asList(args).contains("--verbose"));
        System.exit(execute(commandLine(args), args));
    }

    /**
     * Runs the command line. Running out of heap (an {@link OutOfMemoryError}, which picocli does not catch) becomes
     * one line for a person, with the heap's size and what to do, and exit status 1; staged output files are
     * already deleted by then.
     */
    static int execute(CommandLine cl, String[] args) {
        try {
            return cl.execute(args);
        } catch (OutOfMemoryError e) {
            java.io.PrintWriter err = cl.getErr();
            err.println("jdem846: out of memory: the grid and the picture do not fit in the Java heap (at most "
                    + heapSize() + "); " + HEAP_ADVICE);
            err.flush();
            return 1;
        }
    }

    /** What to do about a picture too large for the heap. */
    static final String HEAP_ADVICE = "make a smaller picture with --scale, --width or --window, lower --memory"
            + " (a picture above it is rendered in tiles), or give Java more heap, e.g. java -Xmx8g -jar"
            + " jdem846-cli.jar …";

    private static String heapSize() {
        double mib = Runtime.getRuntime().maxMemory() / 1048576.0;
        return mib < 1024 ? String.format(java.util.Locale.ROOT, "%.0f MiB", mib)
                : String.format(java.util.Locale.ROOT, "%.1f GiB", mib / 1024);
    }

    /**
     * Shows Apache SIS's log records only with --verbose ({@link LibraryLogConfig}). The log manager reads that
     * configuration when something first logs; when the JVM was given a configuration of its own, SIS's level is
     * added to it now.
     */
    private static void configureLibraryLogs(boolean verbose) {
        String level = verbose ? "INFO" : "OFF";
        if (System.getProperty("java.util.logging.config.class") == null
                && System.getProperty("java.util.logging.config.file") == null) {
            System.setProperty(LibraryLogConfig.LEVEL_PROPERTY, level);
            System.setProperty("java.util.logging.config.class", LibraryLogConfig.class.getName());
            return;
        }
        try {
            java.util.logging.LogManager.getLogManager().updateConfiguration(
                    new java.io.ByteArrayInputStream(("org.apache.sis.level = " + level + "\n").getBytes(
                            java.nio.charset.StandardCharsets.ISO_8859_1)),
                    key -> (old, now) -> now != null ? now : old);
        } catch (java.io.IOException e) {
            // keep the JVM's configuration
        }
    }
}
