package io.github.jdem846.bench;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.ForkJoinPool;

/**
 * The accuracy study of docs/accuracy.md: cast-shadow disagreement with {@code exact} against run time.
 *
 * <pre>
 * java -Xmx6g -cp target/benchmarks.jar io.github.jdem846.bench.ShadowAccuracyStudy measure --dem bigtujunga \
 *      [--elevations 2,5,10,20,45] [--azimuths 0,30,45,100,135,160,200,215,250,280,300,330] \
 *      [--sample 200000] [--seed 846] [--threads 2] [--testdata testdata] [--out docs/accuracy]
 * java -cp target/benchmarks.jar io.github.jdem846.bench.ShadowAccuracyStudy report \
 *      [--in docs/accuracy] [--images docs/images] [--doc docs/accuracy/results.md]
 * </pre>
 * {@code measure} writes one CSV per DEM and elevation ({@code OUT/DEM-eELEVATION.csv}), so a long study runs in
 * pieces; {@code --sample 0} compares every valid cell. {@code report} reads every CSV in {@code --in} and writes
 * the work-precision plots and the Markdown tables (into {@code --doc} between its generated-tables markers, or as
 * the whole file when it has none). {@code diagnose} tells, for one method's disagreements, how many lie on exact's
 * shadow edges and how far the sun must move for exact to agree ({@link AccuracyDiagnosis}), and can draw a map of
 * them; {@code converge} compares {@code exact} with finer marches ({@link ReferenceConvergence}); {@code rowsweep}
 * measures the row-by-row re-interpolating sweep the issue warns about ({@link RowByRowSweep}) next to ours;
 * {@code border} measures how much of the disagreement comes from the grid's edge ({@link NoDataBorderCheck}).
 */
public final class ShadowAccuracyStudy {

    /** Off-axis azimuths as well as the axes and diagonals, where rays pass through cell centres. */
    static final String DEFAULT_AZIMUTHS = "0,30,45,100,135,160,200,215,250,280,300,330";

    private static final List<String> COMMANDS = List.of("measure", "report", "diagnose", "converge", "rowsweep",
            "border");

    private ShadowAccuracyStudy() {
    }

    public static void main(String[] args) throws IOException {
        if (args.length == 0 || !COMMANDS.contains(args[0])) {
            usage("expected one of " + COMMANDS + " first");
        }
        Map<String, String> opt = options(Arrays.copyOfRange(args, 1, args.length));
        if (args[0].equals("measure")) {
            measure(opt, String.join(" ", args));
        } else if (args[0].equals("diagnose")) {
            diagnose(opt, String.join(" ", args));
        } else if (args[0].equals("converge")) {
            converge(opt, String.join(" ", args));
        } else if (args[0].equals("rowsweep")) {
            rowSweep(opt, String.join(" ", args));
        } else if (args[0].equals("border")) {
            border(opt, String.join(" ", args));
        } else {
            AccuracyReport.write(Path.of(opt.getOrDefault("in", "docs/accuracy")),
                    Path.of(opt.getOrDefault("images", "docs/images")),
                    Path.of(opt.getOrDefault("doc", "docs/accuracy/results.md")));
        }
    }

    private static void measure(Map<String, String> opt, String command) throws IOException {
        String name = opt.get("dem");
        if (name == null) {
            usage("measure needs --dem, one of " + StudyDem.NAMES);
        }
        double[] elevations = numbers(opt.getOrDefault("elevations", "2,5,10,20,45"), "--elevations");
        double[] azimuths = numbers(opt.getOrDefault("azimuths", DEFAULT_AZIMUTHS), "--azimuths");
        int sample = Integer.parseInt(opt.getOrDefault("sample", "200000"));
        long seed = Long.parseLong(opt.getOrDefault("seed", "846"));
        int threads = Integer.parseInt(opt.getOrDefault("threads",
                Integer.toString(Runtime.getRuntime().availableProcessors())));
        Path out = Path.of(opt.getOrDefault("out", "docs/accuracy"));
        Files.createDirectories(out);
        StudyDem dem = StudyDem.load(name, Path.of(opt.getOrDefault("testdata", "testdata")));
        ForkJoinPool pool = new ForkJoinPool(threads);
        try {
            AccuracyMeasurement m = new AccuracyMeasurement(dem, pool, sample, seed);
            System.err.printf(Locale.ROOT, "%s: %d×%d, %d cells evaluated (%s), %d threads%n", name,
                    dem.dem().width(), dem.dem().height(), m.evaluatedCells(),
                    m.exhaustive() ? "every valid cell" : "random sample, seed " + seed, threads);
            m.warmUp();
            for (double e : elevations) {
                List<AccuracyRow> rows = new ArrayList<>();
                for (double a : azimuths) {
                    long t0 = System.nanoTime();
                    List<AccuracyRow> r = m.measure(e, a);
                    rows.addAll(r);
                    System.err.printf(Locale.ROOT, "  e=%s a=%s: %.1f s; sweep %.3f %%, article march %.3f %%%n",
                            e, a, (System.nanoTime() - t0) * 1e-9, 100 * find(r, StudyMethod.SWEEP).fraction(),
                            100 * find(r, StudyMethod.MARCH_ARTICLE).fraction());
                }
                Path file = out.resolve(name + "-e" + fileNumber(e) + ".csv");
                try (PrintWriter w = new PrintWriter(Files.newBufferedWriter(file, StandardCharsets.UTF_8))) {
                    w.println("# " + command);
                    w.println("# " + Instant.now() + ", " + System.getProperty("java.vm.name") + " "
                            + System.getProperty("java.version") + ", " + threads + " threads, "
                            + Runtime.getRuntime().availableProcessors() + " CPUs");
                    w.println("# " + dem.description());
                    w.println(AccuracyRow.HEADER);
                    for (AccuracyRow r : rows) {
                        w.println(r.toCsv());
                    }
                }
                System.err.println("wrote " + file);
            }
        } finally {
            pool.shutdownNow();
        }
    }

    private static void diagnose(Map<String, String> opt, String command) throws IOException {
        String name = opt.get("dem");
        if (name == null) {
            usage("diagnose needs --dem, one of " + StudyDem.NAMES);
        }
        StudyMethod method = StudyMethod.ofKey(opt.getOrDefault("method", "sweep"));
        double[] elevations = numbers(opt.getOrDefault("elevations", "5,20"), "--elevations");
        double[] azimuths = numbers(opt.getOrDefault("azimuths", DEFAULT_AZIMUTHS), "--azimuths");
        int sample = Integer.parseInt(opt.getOrDefault("sample", "200000"));
        long seed = Long.parseLong(opt.getOrDefault("seed", "846"));
        String mapAzimuth = opt.get("map-azimuth");
        Path images = Path.of(opt.getOrDefault("images", "docs/images"));
        Path out = Path.of(opt.getOrDefault("out", "docs/accuracy/diagnosis-" + name + "-" + method.key() + ".md"));
        StudyDem dem = StudyDem.load(name, Path.of(opt.getOrDefault("testdata", "testdata")));
        int[] valid = AccuracyMeasurement.validCells(dem.dem());
        int[] cells = sample <= 0 || sample >= valid.length ? valid
                : AccuracyMeasurement.sample(valid, sample, seed);
        ForkJoinPool pool = new ForkJoinPool(Runtime.getRuntime().availableProcessors());
        StringBuilder md = new StringBuilder();
        md.append("<!-- ").append(command).append(" -->\n");
        md.append(String.format(Locale.ROOT, "%s vs exact on %s (%,d cells%s)%n%n", method.label,
                dem.description(), cells.length, cells.length == valid.length ? ", every valid cell"
                        : ", random sample, seed " + seed));
        md.append(AccuracyDiagnosis.header()).append('\n');
        try {
            AccuracyDiagnosis d = new AccuracyDiagnosis(dem.dem(), pool);
            for (double e : elevations) {
                for (double a : azimuths) {
                    Path map = mapAzimuth != null && Double.parseDouble(mapAzimuth) == a
                            ? images.resolve("accuracy-diff-" + name + "-" + method.key() + "-e" + fileNumber(e)
                                    + "-a" + fileNumber(a) + ".png")
                            : null;
                    String row = d.row(method, e, a, cells, map);
                    md.append(row).append('\n');
                    System.err.println(row);
                }
            }
        } finally {
            pool.shutdownNow();
        }
        Files.writeString(out, md, StandardCharsets.UTF_8);
        System.err.println("wrote " + out);
    }

    private static void converge(Map<String, String> opt, String command) throws IOException {
        String name = opt.get("dem");
        if (name == null) {
            usage("converge needs --dem, one of " + StudyDem.NAMES);
        }
        double[] elevations = numbers(opt.getOrDefault("elevations", "2,5,20"), "--elevations");
        double[] azimuths = numbers(opt.getOrDefault("azimuths", "100,160,250,300"), "--azimuths");
        int sample = Integer.parseInt(opt.getOrDefault("sample", "20000"));
        long seed = Long.parseLong(opt.getOrDefault("seed", "846"));
        Path out = Path.of(opt.getOrDefault("out", "docs/accuracy/convergence-" + name + ".md"));
        StudyDem dem = StudyDem.load(name, Path.of(opt.getOrDefault("testdata", "testdata")));
        int[] valid = AccuracyMeasurement.validCells(dem.dem());
        int[] cells = sample <= 0 || sample >= valid.length ? valid
                : AccuracyMeasurement.sample(valid, sample, seed);
        ForkJoinPool pool = new ForkJoinPool(Runtime.getRuntime().availableProcessors());
        StringBuilder md = new StringBuilder("<!-- " + command + " -->\n");
        md.append(String.format(Locale.ROOT, "exact vs finer bilinear marches on %s (%,d cells)%n%n",
                dem.description(), cells.length));
        md.append(ReferenceConvergence.header()).append('\n');
        try {
            for (double e : elevations) {
                for (double a : azimuths) {
                    String row = ReferenceConvergence.row(dem.dem(), pool, e, a, cells);
                    md.append(row).append('\n');
                    System.err.println(row);
                }
            }
        } finally {
            pool.shutdownNow();
        }
        Files.writeString(out, md, StandardCharsets.UTF_8);
        System.err.println("wrote " + out);
    }

    private static void rowSweep(Map<String, String> opt, String command) throws IOException {
        String name = opt.get("dem");
        if (name == null) {
            usage("rowsweep needs --dem, one of " + StudyDem.NAMES);
        }
        double[] elevations = numbers(opt.getOrDefault("elevations", "5,20"), "--elevations");
        double[] azimuths = numbers(opt.getOrDefault("azimuths", "90," + DEFAULT_AZIMUTHS), "--azimuths");
        Path out = Path.of(opt.getOrDefault("out", "docs/accuracy/rowsweep-" + name + ".md"));
        StudyDem dem = StudyDem.load(name, Path.of(opt.getOrDefault("testdata", "testdata")));
        int[] valid = AccuracyMeasurement.validCells(dem.dem());
        int sample = Integer.parseInt(opt.getOrDefault("sample", "0"));
        long seed = Long.parseLong(opt.getOrDefault("seed", "846"));
        int[] cells = sample <= 0 || sample >= valid.length ? valid
                : AccuracyMeasurement.sample(valid, sample, seed);
        ForkJoinPool pool = new ForkJoinPool(Runtime.getRuntime().availableProcessors());
        StringBuilder md = new StringBuilder("<!-- " + command + " -->\n");
        md.append(String.format(Locale.ROOT, "%% of cells ≠ exact on %s (%s, %,d)%n%n", dem.description(),
                cells.length == valid.length ? "every valid cell" : "random sample, seed " + seed, cells.length));
        md.append("| elev. | azim. | row-by-row sweep | sweep (default) | sweep, no first-cell test "
                + "| march 1 cell, bilinear | row-by-row = march 1 cell? |\n|---:|---:|---:|---:|---:|---:|---|\n");
        try {
            for (double e : elevations) {
                for (double a : azimuths) {
                    io.github.jdem846.light.LightDirection light = new io.github.jdem846.light.LightDirection(a, e);
                    float[] exact = StudyMethod.EXACT.algorithm.computeCells(dem.dem(), light,
                            StudyMethod.EXACT.options, pool, cells);
                    float[] rows = RowByRowSweep.compute(dem.dem(), light);
                    float[] sweep = StudyMethod.SWEEP.algorithm.compute(dem.dem(), light, StudyMethod.SWEEP.options,
                            pool).backingArray();
                    float[] noFirst = StudyMethod.SWEEP_NO_FIRST_CELL.algorithm.compute(dem.dem(), light,
                            StudyMethod.SWEEP_NO_FIRST_CELL.options, pool).backingArray();
                    float[] march1 = StudyMethod.MARCH_1_BILINEAR.algorithm.computeCells(dem.dem(), light,
                            StudyMethod.MARCH_1_BILINEAR.options, pool, cells);
                    long dr = 0;
                    long ds = 0;
                    long dn = 0;
                    long dm = 0;
                    long rm = 0;
                    for (int q = 0; q < cells.length; q++) {
                        boolean x = exact[q] >= 0.5f;
                        int c = cells[q];
                        dr += (rows[c] >= 0.5f) != x ? 1 : 0;
                        ds += (sweep[c] >= 0.5f) != x ? 1 : 0;
                        dn += (noFirst[c] >= 0.5f) != x ? 1 : 0;
                        dm += (march1[q] >= 0.5f) != x ? 1 : 0;
                        rm += (rows[c] >= 0.5f) != (march1[q] >= 0.5f) ? 1 : 0;
                    }
                    double n = cells.length / 100.0;
                    String row = String.format(Locale.ROOT, "| %s | %s | %.3f | %.3f | %.3f | %.3f | %s |",
                            fileNumber(e), fileNumber(a), dr / n, ds / n, dn / n, dm / n,
                            rm == 0 ? "yes" : String.format(Locale.ROOT, "no (%.3f %% differ)", rm / n));
                    md.append(row).append('\n');
                    System.err.println(row);
                }
            }
        } finally {
            pool.shutdownNow();
        }
        Files.writeString(out, md, StandardCharsets.UTF_8);
        System.err.println("wrote " + out);
    }

    private static void border(Map<String, String> opt, String command) throws IOException {
        String name = opt.get("dem");
        if (name == null) {
            usage("border needs --dem, one of " + StudyDem.NAMES);
        }
        StudyMethod method = StudyMethod.ofKey(opt.getOrDefault("method", "sweep"));
        double[] elevations = numbers(opt.getOrDefault("elevations", "5"), "--elevations");
        double[] azimuths = numbers(opt.getOrDefault("azimuths", "45,160,250"), "--azimuths");
        int width = Integer.parseInt(opt.getOrDefault("border", "3"));
        Path out = Path.of(opt.getOrDefault("out", "docs/accuracy/border-" + name + "-" + method.key() + ".md"));
        StudyDem dem = StudyDem.load(name, Path.of(opt.getOrDefault("testdata", "testdata")));
        ForkJoinPool pool = new ForkJoinPool(Runtime.getRuntime().availableProcessors());
        StringBuilder md = new StringBuilder("<!-- " + command + " -->\n");
        md.append(String.format(Locale.ROOT, "%s vs exact on %s, as is and framed by %d no-data cells%n%n",
                method.label, dem.description(), width));
        md.append(NoDataBorderCheck.header()).append('\n');
        try {
            for (double e : elevations) {
                for (double a : azimuths) {
                    String row = NoDataBorderCheck.row(dem.dem(), method, width, e, a, pool);
                    md.append(row).append('\n');
                    System.err.println(row);
                }
            }
        } finally {
            pool.shutdownNow();
        }
        Files.writeString(out, md, StandardCharsets.UTF_8);
        System.err.println("wrote " + out);
    }

    private static AccuracyRow find(List<AccuracyRow> rows, StudyMethod m) {
        return rows.stream().filter(r -> r.method() == m).findFirst().orElseThrow();
    }

    private static String fileNumber(double d) {
        return d == Math.rint(d) ? Long.toString((long) d) : Double.toString(d);
    }

    private static double[] numbers(String list, String option) {
        try {
            return Arrays.stream(list.split(",")).map(String::trim).mapToDouble(Double::parseDouble).toArray();
        } catch (NumberFormatException e) {
            usage(option + " must be a comma-separated list of numbers, got '" + list + "'");
            return null;
        }
    }

    private static Map<String, String> options(String[] args) {
        Map<String, String> m = new LinkedHashMap<>();
        for (int i = 0; i < args.length; i++) {
            if (!args[i].startsWith("--") || i + 1 >= args.length) {
                usage("expected --option value pairs, got '" + args[i] + "'");
            }
            m.put(args[i].substring(2), args[++i]);
        }
        return m;
    }

    private static void usage(String problem) {
        System.err.println("ShadowAccuracyStudy: " + problem);
        System.err.println("usage: ShadowAccuracyStudy measure --dem NAME [--elevations LIST] [--azimuths LIST]"
                + " [--sample N|0] [--seed S] [--threads T] [--testdata DIR] [--out DIR]");
        System.err.println("       ShadowAccuracyStudy report [--in DIR] [--images DIR] [--doc FILE]");
        System.err.println("       ShadowAccuracyStudy diagnose --dem NAME [--method KEY] [--elevations LIST]"
                + " [--azimuths LIST] [--sample N|0] [--map-azimuth A] [--images DIR] [--out FILE]");
        System.err.println("       ShadowAccuracyStudy converge --dem NAME [--elevations LIST] [--azimuths LIST]"
                + " [--sample N|0] [--out FILE]");
        System.err.println("       ShadowAccuracyStudy border --dem NAME [--method KEY] [--elevations LIST]"
                + " [--azimuths LIST] [--border CELLS] [--out FILE]");
        System.err.println("       ShadowAccuracyStudy rowsweep --dem NAME [--elevations LIST] [--azimuths LIST]"
                + " [--sample N|0] [--out FILE]");
        System.exit(2);
    }
}
