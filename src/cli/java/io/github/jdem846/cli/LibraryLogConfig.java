package io.github.jdem846.cli;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.SequenceInputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.logging.LogManager;

/**
 * The command line's java.util.logging configuration: the JDK's own ({@code conf/logging.properties}) plus the level
 * of Apache SIS's loggers, {@code OFF}, or {@code INFO} with {@code --verbose} ({@link #LEVEL_PROPERTY}). SIS reports
 * through java.util.logging ("SIS_DATA is not set", WKT elements it ignores); what matters of that reaches the user
 * as the command's own notices, and setting the level also keeps the library from quieting SIS itself
 * ({@code internal.SisLoggers}).
 *
 * <p>Named in {@code java.util.logging.config.class} by {@link Main}, so that the configuration is read when
 * something first logs, not at start: the log manager's start-up took about 20 ms of every command, and most
 * commands (a hillshade of a GeoTIFF, say) never start Apache SIS or log at all.
 */
public final class LibraryLogConfig {

    /** The system property holding the level for Apache SIS's loggers. */
    static final String LEVEL_PROPERTY = "jdem846.cli.sisLogLevel";

    /** The JDK's configuration where a JDK image has none. */
    private static final String JDK_DEFAULTS = "handlers = java.util.logging.ConsoleHandler\n.level = INFO\n"
            + "java.util.logging.ConsoleHandler.level = INFO\n"
            + "java.util.logging.ConsoleHandler.formatter = java.util.logging.SimpleFormatter\n";

    /** Called by the log manager as it reads its configuration; reads the one described above into it. */
    public LibraryLogConfig() throws IOException {
        String level = System.getProperty(LEVEL_PROPERTY, "OFF");
        Path jdk = Path.of(System.getProperty("java.home"), "conf", "logging.properties");
        InputStream defaults = Files.isRegularFile(jdk) ? Files.newInputStream(jdk)
                : new ByteArrayInputStream(JDK_DEFAULTS.getBytes(StandardCharsets.ISO_8859_1));
        try (InputStream config = new SequenceInputStream(defaults, new ByteArrayInputStream(
                ("\norg.apache.sis.level = " + level + "\n").getBytes(StandardCharsets.ISO_8859_1)))) {
            LogManager.getLogManager().readConfiguration(config);
        }
    }
}
