package io.github.jdem846;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The distribution's launcher, {@code bin/jdem846} of the unpacked {@code jdem846-<version>-dist.zip}, on the JDK
 * that runs the tests (its {@code JAVA_HOME}): it runs {@code lib/jdem846-cli.jar} and, on JDK 19 and later, makes
 * a class-data archive in {@code $XDG_CACHE_HOME/jdem846} on the first command that does work and loads the CLI's
 * classes from it after; on JDK 25 and later, once that archive exists, each command's next run records for an
 * ahead-of-time cache of the command, which the runs after map. Small jobs run with the first-tier JIT only.
 */
class LauncherIT {

    private static final Path DIST = Path.of(System.getProperty("jdem846.distDir"));

    @Test
    void theDistributionHoldsTheLauncherTheJarAndTheTexts() {
        for (String f : List.of("bin/jdem846", "bin/jdem846.bat", "lib/jdem846-cli.jar", "LICENSE", "README.md")) {
            assertTrue(Files.isRegularFile(DIST.resolve(f)), f);
        }
        assertTrue(Files.isExecutable(DIST.resolve("bin/jdem846")), "bin/jdem846 is executable");
    }

    @Test
    void versionRunsTheJarAndMakesNoArchive(@TempDir Path cache) throws Exception {
        Run run = launch(cache, Map.of(), "--version");
        assertEquals(0, run.status(), run.out());
        assertTrue(run.out().startsWith("jdem846 "), run.out());
        assertTrue(run.out().contains("Java " + System.getProperty("java.version")), "on JAVA_HOME's JVM: " + run.out());
        assertEquals(List.of(), archives(cache));
    }

    @Test
    void theFirstCommandMakesTheArchiveAndTheNextLoadsTheCliFromIt(@TempDir Path cache) throws Exception {
        Run first = launch(cache, Map.of(), "info", "--json");
        assertEquals(0, first.status(), first.out());
        assertJsonAlone(first);

        int feature = Runtime.version().feature();
        List<Path> made = archives(cache);
        if (feature < 19) {
            assertEquals(List.of(), made, "JDK 17 and 18 start with the JDK's own archive only");
            return;
        }
        assertEquals(1, made.size(), made.toString());
        String name = made.get(0).getFileName().toString();
        assertTrue(name.startsWith("jdem846-" + feature + "-") && name.endsWith(".jsa"), name);
        assertTrue(Files.size(made.get(0)) > 100_000, "an archive of the classes loaded");

        if (feature >= 25) {
            // the archive shows that jdem846 runs here again: this run records, and a background JVM makes the cache
            Run second = launch(cache, Map.of(), "info", "--json");
            assertEquals(0, second.status(), second.out());
            assertJsonAlone(second);
            made = awaitCache(cache, "info");
            assertEquals(2, made.size(), made.toString());
            assertTrue(made.get(0).getFileName().toString().endsWith("-info.aot"), made.toString());
        }

        Run next = launch(cache, Map.of("JDEM846_OPTS", "-Xlog:class+load=info"), "info", "--json");
        assertEquals(0, next.status(), next.out());
        String shared = " io.github.jdem846.cli.Main source: shared objects file" + (feature >= 25 ? "" : " (top)");
        assertTrue(next.out().lines().anyMatch(l -> l.endsWith(shared)),
                next.out().lines().filter(l -> l.contains("cli.Main")).toList().toString());
        assertEquals(made, archives(cache), "the same caches, used");
    }

    @Test
    void eachCommandGetsItsOwnAheadOfTimeCacheOnJdk25(@TempDir Path cache) throws Exception {
        assumeTrue(Runtime.version().feature() >= 25, "ahead-of-time caches need JDK 25");
        assertEquals(0, launch(cache, Map.of(), "info").status());
        assertEquals(0, launch(cache, Map.of(), "info").status());
        awaitCache(cache, "info");
        Run sun = launch(cache, Map.of(), "sun", "--at", "34.3,-118.1", "--time", "2026-06-21T12:00Z");
        assertEquals(0, sun.status(), sun.out());
        List<Path> made = awaitCache(cache, "sun");
        assertEquals(3, made.size(), "the archive and a cache for each command: " + made);
        assertTrue(made.stream().anyMatch(f -> f.getFileName().toString().endsWith("-info.aot")), made.toString());
    }

    @Test
    void aFailedRecordingMakesNoCacheAndKeepsItsExitStatus(@TempDir Path cache) throws Exception {
        assertEquals(0, launch(cache, Map.of(), "info").status(), "the archive, so that the next run records");
        Run run = launch(cache, Map.of(), "info", cache.resolve("missing.flt").toString());
        assertEquals(1, run.status(), run.out());
        assertTrue(run.out().contains("missing.flt"), run.out());
        assertEquals(List.of(), leftOver(cache).stream().filter(f -> f.toString().contains(".aot")).toList(),
                "no ahead-of-time cache and no lock after a failed run");
    }

    @Test
    void whileAnotherRunRecordsTheCommandRunsWithTheClassDataArchive(@TempDir Path cache) throws Exception {
        assumeTrue(Runtime.version().feature() >= 25, "ahead-of-time caches need JDK 25");
        assertEquals(0, launch(cache, Map.of(), "info").status());
        Path archive = archives(cache).get(0);
        Path lock = Files.createDirectory(Path.of(archive.toString().replace(".jsa", "-sun.aot.lock")));

        Run sun = launch(cache, Map.of("JDEM846_OPTS", "-Xlog:class+load=info"), "sun", "--at", "34.3,-118.1",
                "--time", "2026-06-21T12:00Z");
        assertEquals(0, sun.status(), sun.out());
        assertTrue(sun.out().lines().anyMatch(l -> l.endsWith(" picocli.CommandLine source: shared objects file"
                + " (top)")), "from the class-data archive");
        assertEquals(List.of(archive), archives(cache), "no recording");
        assertTrue(Files.isDirectory(lock), "the other run's lock is left alone");
    }

    @Test
    void aNewArchiveDropsArchivesUnusedFor30Days(@TempDir Path cache) throws Exception {
        Path dir = Files.createDirectories(cache.resolve("jdem846"));
        Path stale = Files.write(dir.resolve("jdem846-21-111.jsa"), new byte[16]);
        Path staleAot = Files.write(dir.resolve("jdem846-25-111-render.aot"), new byte[16]);
        Path recent = Files.write(dir.resolve("jdem846-21-222.jsa"), new byte[16]);
        long day = TimeUnit.DAYS.toMillis(1);
        for (Path old : List.of(stale, staleAot)) {
            Files.setLastModifiedTime(old, java.nio.file.attribute.FileTime.fromMillis(System.currentTimeMillis()
                    - 40 * day));
        }
        Files.setLastModifiedTime(recent, java.nio.file.attribute.FileTime.fromMillis(System.currentTimeMillis()
                - 2 * day));

        Run run = launch(cache, Map.of(), "info", "--json");
        assertEquals(0, run.status(), run.out());
        List<Path> left = archives(cache);
        if (Runtime.version().feature() < 19) {
            assertEquals(List.of(recent, stale, staleAot).stream().sorted().toList(), left,
                    "no archive work on JDK 17 and 18");
            return;
        }
        assertFalse(left.contains(stale) || left.contains(staleAot), "caches 40 days old are deleted: " + left);
        assertTrue(left.contains(recent), "one 2 days old stays: " + left);
        assertEquals(2, left.size(), "and the new one is made: " + left);
    }

    @Test
    void smallJobsRunWithTheFirstTierCompilerOnly(@TempDir Path cache) throws Exception {
        Path dem = Path.of("testdata/dem/bigtujunga_srtm30m_utm11n.tif").toAbsolutePath();
        Path out = cache.resolve("out.png").toAbsolutePath();
        assertEquals(1, tier(cache, "hillshade", dem.toString(), "-o", out.toString()), "a 1197 x 643 hillshade");
        assertEquals(1, tier(cache, "render", "--shadows", "sweep", dem.toString(), "-o", out.toString()));
        assertEquals(4, tier(cache, "render", "--ambient", "0.3", dem.toString(), "-o", out.toString()),
                "sky light is heavy work");
        assertEquals(4, tier(cache, "shadows", "--algorithm=march", dem.toString(), "-o", out.toString()));
        assertEquals(4, tier(cache, "skyview", dem.toString(), "-o", out.toString()));
        assertEquals(4, tier(cache, "hillshade", cache.toString(), "-o", out.toString()), "a folder: a mosaic");
        Path big = sparseFile(cache.resolve("big.flt"), 17L << 20);
        assertEquals(processors() <= 2 ? 1 : 4, tier(cache, "hillshade", big.toString(), "-o", out.toString()),
                "17 MiB of input: little work with one or two processors only");
        Path huge = sparseFile(cache.resolve("huge.flt"), 257L << 20);
        assertEquals(4, tier(cache, "hillshade", huge.toString(), "-o", out.toString()), "257 MiB of input");
        assertEquals(1, tier(cache, "hillshade", dem.toString(), "-o", huge.toString()),
                "an existing output file is not input");
        assertEquals(4, tierWithOptions(cache, "-XX:TieredStopAtLevel=4", "hillshade", dem.toString(), "-o",
                out.toString()), "JDEM846_OPTS chooses the compiler");
    }

    private static Path sparseFile(Path file, long length) throws IOException {
        try (java.io.RandomAccessFile f = new java.io.RandomAccessFile(file.toFile(), "rw")) {
            f.setLength(length);
        }
        return file;
    }

    /** The processors the launcher sees ({@code getconf _NPROCESSORS_ONLN}). */
    private static int processors() throws Exception {
        Process p = new ProcessBuilder("getconf", "_NPROCESSORS_ONLN").redirectErrorStream(true).start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8).strip();
        assertTrue(p.waitFor(30, TimeUnit.SECONDS), "getconf finished");
        return Integer.parseInt(out);
    }

    /**
     * The JIT's highest tier the launcher chose for a command (which may fail: only the JVM's flags count), checking
     * that the first tier comes with the hillshade kernels' fused loops ({@code -Djdem846.kernels=fused}) and the
     * optimising compiler without.
     */
    private static int tier(Path cache, String... args) throws Exception {
        return tierWithOptions(cache, "", args);
    }

    /** {@link #tier} with {@code opts} in JDEM846_OPTS. */
    private static int tierWithOptions(Path cache, String opts, String... args) throws Exception {
        Run run = launch(cache, Map.of("JDEM846_CDS", "off", "JDEM846_OPTS",
                "-XX:+PrintFlagsFinal -XshowSettings:properties " + opts), args);
        String line = run.out().lines().filter(l -> l.matches("\\s*intx TieredStopAtLevel\\s*=.*")).findFirst()
                .orElseThrow(() -> new AssertionError(run.out()));
        int tier = Integer.parseInt(line.replaceAll(".*=\\s*(\\d+).*", "$1"));
        boolean fused = run.out().lines().anyMatch(l -> l.strip().equals("jdem846.kernels = fused"));
        assertTrue(run.out().lines().anyMatch(l -> l.strip().equals("jdk.reflect.useNativeAccessorOnly = true")),
                "core reflection through native accessors");
        assertEquals(tier == 1, fused, "fused kernels with the first tier only: " + String.join(" ", args));
        return tier;
    }

    private record Run(int status, String out) {
    }

    private static Run launch(Path cache, Map<String, String> env, String... args) throws Exception {
        List<String> command = new ArrayList<>(List.of(DIST.resolve("bin/jdem846").toString()));
        command.addAll(List.of(args));
        ProcessBuilder builder = new ProcessBuilder(command).redirectErrorStream(true);
        builder.environment().put("JAVA_HOME", System.getProperty("java.home"));
        builder.environment().put("XDG_CACHE_HOME", cache.toString());
        builder.environment().remove("JDEM846_OPTS");
        builder.environment().remove("JDEM846_CDS");
        builder.environment().putAll(env);
        Process p = builder.start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(p.waitFor(120, TimeUnit.SECONDS), "finished");
        return new Run(p.exitValue(), out);
    }

    /** Checks that stdout is the JSON alone: no class-data sharing or recording message. */
    private static void assertJsonAlone(Run run) {
        String json = run.out().strip();
        assertTrue(json.startsWith("{\"file\": \"bundled sample ") && json.endsWith("}") && json.lines().count() == 1,
                json);
    }

    /** The class-data archives and ahead-of-time caches made. */
    private static List<Path> archives(Path cache) throws IOException {
        return leftOver(cache).stream().filter(f -> f.toString().endsWith(".jsa") || f.toString().endsWith(".aot"))
                .toList();
    }

    /** Everything in the launcher's cache folder. */
    private static List<Path> leftOver(Path cache) throws IOException {
        Path dir = cache.resolve("jdem846");
        if (!Files.isDirectory(dir)) {
            return List.of();
        }
        try (Stream<Path> files = Files.list(dir)) {
            return files.sorted().toList();
        }
    }

    /**
     * Waits for the ahead-of-time cache of the command, which a background JVM makes after the command's first run,
     * and for that run's lock to go; then returns the caches and archives made.
     */
    private static List<Path> awaitCache(Path cache, String command) throws Exception {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(120);
        while (System.nanoTime() < deadline) {
            List<Path> files = leftOver(cache);
            boolean made = files.stream().anyMatch(f -> f.toString().endsWith("-" + command + ".aot"));
            boolean locked = files.stream().anyMatch(f -> f.toString().endsWith("-" + command + ".aot.lock"));
            if (made && !locked) {
                return archives(cache);
            }
            if (!locked) {
                throw new AssertionError("no cache made and no recording under way: " + files);
            }
            Thread.sleep(100);
        }
        throw new AssertionError("the cache of " + command + " was not made in 120 s: " + leftOver(cache));
    }
}
