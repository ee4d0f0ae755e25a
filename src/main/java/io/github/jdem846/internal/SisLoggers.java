package io.github.jdem846.internal;

import java.util.ArrayList;
import java.util.List;
import java.util.logging.Level;
import java.util.logging.Logger;

/**
 * Keeps Apache SIS's routine warnings off the embedding application's stderr: SIS reports through
 * java.util.logging, whose default console handler prints warnings, and would print {@code The "SIS_DATA"
 * environment variable is not set} once per JVM (on the first EPSG code, e.g. when a {@code .prj} is written) and
 * the WKT elements it ignores when parsing a {@code .prj}. What matters of these reaches the user as the library's
 * own notices.
 *
 * <p>Only the loggers named in {@link #NAMES} are touched, and only those the application left unconfigured: a
 * logger whose level, or whose ancestor's level below the root, is set (in {@code logging.properties} or by
 * {@link Logger#setLevel}) is left as it is. The others get level {@link Level#SEVERE}: SIS's warnings and lesser
 * messages are dropped, its errors still go through.
 */
public final class SisLoggers {

    /** The SIS loggers the library's use of SIS writes to: system set-up (SIS_DATA), and WKT parsing. */
    public static final List<String> NAMES = List.of("org.apache.sis.system", "org.apache.sis.io.wkt");

    private SisLoggers() {
    }

    /**
     * Quiets the unconfigured SIS loggers of {@link #NAMES}, once per class loader; called before the library's
     * first use of Apache SIS.
     *
     * @return the loggers whose level this class set (empty when the application configured all of them)
     */
    public static List<Logger> quiet() {
        return Quieted.LOGGERS;
    }

    /** The loggers quieted, held so that they keep their level (java.util.logging holds loggers weakly). */
    private static final class Quieted {
        static final List<Logger> LOGGERS = quietUnconfigured();
    }

    private static List<Logger> quietUnconfigured() {
        List<Logger> quieted = new ArrayList<>();
        for (String name : NAMES) {
            Logger logger = Logger.getLogger(name);
            if (!configured(logger)) {
                logger.setLevel(Level.SEVERE);
                quieted.add(logger);
            }
        }
        return List.copyOf(quieted);
    }

    /** Whether the logger or one of its ancestors below the root has a level of its own. */
    private static boolean configured(Logger logger) {
        for (Logger l = logger; l != null && !l.getName().isEmpty(); l = l.getParent()) {
            if (l.getLevel() != null) {
                return true;
            }
        }
        return false;
    }
}
