package io.github.jdem846.spark;

import io.github.jdem846.cli.TilesCommand;
import io.github.jdem846.job.JobListener;
import io.github.jdem846.sun.SunPosition;
import io.github.jdem846.tiles.TileReport;
import java.io.IOException;
import java.io.PrintStream;
import java.io.UncheckedIOException;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Locale;
import org.apache.spark.SparkConf;
import org.apache.spark.api.java.JavaSparkContext;
import picocli.CommandLine;

/**
 * {@code spark-submit jdem846-spark.jar FILE… --zoom MIN-MAX -o OUT [options of jdem846 tiles]}: the tile pyramid
 * rendered on the cluster. Without {@code spark-submit}, {@code spark.master} defaults to {@code local[*]}.
 * Exit status: 0 written, 1 an input could not be read or the output not written, 2 bad usage.
 */
public final class SparkTilesMain {

    private static final String NAME = "jdem846-spark";

    private SparkTilesMain() {
    }

    public static void main(String[] args) {
        System.exit(run(args, System.out, System.err));
    }

    /** Checks the arguments, starts Spark and runs the job; returns the exit status. */
    static int run(String[] args, PrintStream out, PrintStream err) {
        Integer early = checkUsage(args, out, err);
        if (early != null) {
            return early;
        }
        SparkConf conf = new SparkConf().setAppName("jdem846 tiles").setIfMissing("spark.master", "local[*]");
        try (JavaSparkContext sc = new JavaSparkContext(conf)) {
            return run(args, out, err, sc);
        }
    }

    /** The exit status for bad usage, {@code --help} or {@code --version}; null when the job is to run. */
    static Integer checkUsage(String[] args, PrintStream out, PrintStream err) {
        CommandLine cl = new CommandLine(new TilesCommand()).setCommandName("spark-submit " + NAME + ".jar");
        try {
            cl.parseArgs(args);
        } catch (CommandLine.ParameterException e) {
            return usageError(e, err);
        }
        if (cl.isUsageHelpRequested()) {
            cl.usage(out);
            return 0;
        }
        if (cl.isVersionHelpRequested()) {
            cl.printVersionHelp(out);
            return 0;
        }
        return null;
    }

    /** Runs the job on {@code sc}; returns the exit status. */
    static int run(String[] args, PrintStream out, PrintStream err, JavaSparkContext sc) {
        try {
            boolean quiet = TileArguments.of(List.of(args)).parse().quiet();
            Map<String, Long> phases = new LinkedHashMap<>();
            long start = System.nanoTime();
            TileReport report = SparkTiles.run(sc, List.of(args), listener(err, phases));
            long end = System.nanoTime();
            if (quiet) {
                return 0;
            }
            out.printf(Locale.ROOT, "wrote %d tiles (%.1f MB of PNG) to %s in %.1f s (%s)%n", report.written(),
                    report.bytes() / 1e6, report.output(), (end - start) / 1e9, phaseTimes(start, phases));
            for (TileReport.Zoom z : report.zooms()) {
                out.printf(Locale.ROOT, "  zoom %2d: %d tiles written of %d%n", z.z(), z.written(),
                        z.range().count());
            }
            return 0;
        } catch (CommandLine.ParameterException e) {
            return usageError(e, err);
        } catch (IOException | UncheckedIOException | IllegalArgumentException e) {
            err.println(NAME + ": " + Failures.oneLine(e));
            return 1;
        } catch (Exception e) { // SparkException (checked, though no signature says so) after a task's retries
            err.println(NAME + ": " + Failures.oneLine(e));
            return 1;
        }
    }

    private static int usageError(CommandLine.ParameterException e, PrintStream err) {
        err.println(NAME + ": " + e.getMessage());
        err.println("Try '" + NAME + " --help' for more information.");
        return 2;
    }

    /** "read 1.2 s, render 30.1 s, write 0.4 s": the time up to the end of each phase from that of the one before. */
    private static String phaseTimes(long start, Map<String, Long> phases) {
        StringBuilder s = new StringBuilder();
        long last = start;
        for (Map.Entry<String, Long> e : phases.entrySet()) {
            s.append(s.length() == 0 ? "" : ", ").append(e.getKey())
                    .append(String.format(Locale.ROOT, " %.1f s", (e.getValue() - last) / 1e9));
            last = e.getValue();
        }
        return s.toString();
    }

    private static JobListener listener(PrintStream err, Map<String, Long> phases) {
        return new JobListener() {
            @Override
            public void phaseDone(String phase) {
                phases.put(phase, System.nanoTime());
            }

            @Override
            public void notice(String message) {
                err.println(NAME + ": note: " + message);
            }

            @Override
            public void sun(SunPosition p) {
                err.printf(Locale.ROOT, "%s: sun: azimuth %.2f°, elevation %.2f°%n", NAME, p.azimuthDegrees(),
                        p.elevationDegrees());
            }
        };
    }
}
