package io.github.jdem846;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

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
 * classes from it after; small jobs run with the first-tier JIT only.
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
        // stdout is the JSON alone: no class-data sharing message
        String json = first.out().strip();
        assertTrue(json.startsWith("{\"file\": \"bundled sample ") && json.endsWith("}") && json.lines().count() == 1,
                json);

        List<Path> made = archives(cache);
        int feature = Runtime.version().feature();
        if (feature < 19) {
            assertEquals(List.of(), made, "JDK 17 and 18 start with the JDK's own archive only");
            return;
        }
        assertEquals(1, made.size(), made.toString());
        assertTrue(made.get(0).getFileName().toString().startsWith("jdem846-" + feature + "-"), made.toString());
        assertTrue(Files.size(made.get(0)) > 100_000, "an archive of the classes loaded");

        Run next = launch(cache, Map.of("JDEM846_OPTS", "-Xlog:class+load=info"), "info", "--json");
        assertEquals(0, next.status(), next.out());
        assertTrue(next.out().lines().anyMatch(l -> l.endsWith(" io.github.jdem846.cli.Main source: shared objects"
                + " file (top)")), next.out().lines().filter(l -> l.contains("cli.Main")).toList().toString());
        assertEquals(made, archives(cache), "the same archive, used");
    }

    @Test
    void aNewArchiveDropsArchivesUnusedFor30Days(@TempDir Path cache) throws Exception {
        Path dir = Files.createDirectories(cache.resolve("jdem846"));
        Path stale = Files.write(dir.resolve("jdem846-21-111.jsa"), new byte[16]);
        Path recent = Files.write(dir.resolve("jdem846-21-222.jsa"), new byte[16]);
        long day = TimeUnit.DAYS.toMillis(1);
        Files.setLastModifiedTime(stale, java.nio.file.attribute.FileTime.fromMillis(System.currentTimeMillis()
                - 40 * day));
        Files.setLastModifiedTime(recent, java.nio.file.attribute.FileTime.fromMillis(System.currentTimeMillis()
                - 2 * day));

        Run run = launch(cache, Map.of(), "info", "--json");
        assertEquals(0, run.status(), run.out());
        List<Path> left = archives(cache);
        if (Runtime.version().feature() < 19) {
            assertEquals(List.of(recent, stale).stream().sorted().toList(), left, "no archive work on JDK 17 and 18");
            return;
        }
        assertFalse(left.contains(stale), "an archive 40 days old is deleted: " + left);
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
        Path big = cache.resolve("big.flt");
        try (java.io.RandomAccessFile f = new java.io.RandomAccessFile(big.toFile(), "rw")) {
            f.setLength(17L << 20);
        }
        assertEquals(4, tier(cache, "hillshade", big.toString(), "-o", out.toString()), "17 MiB of input");
        assertEquals(1, tier(cache, "hillshade", dem.toString(), "-o", big.toString()),
                "an existing output file is not input");
    }

    /** The JIT's highest tier the launcher chose for a command (which may fail: only the JVM's flags count). */
    private static int tier(Path cache, String... args) throws Exception {
        Run run = launch(cache, Map.of("JDEM846_CDS", "off", "JDEM846_OPTS", "-XX:+PrintFlagsFinal"), args);
        String line = run.out().lines().filter(l -> l.matches("\\s*intx TieredStopAtLevel\\s*=.*")).findFirst()
                .orElseThrow(() -> new AssertionError(run.out()));
        return Integer.parseInt(line.replaceAll(".*=\\s*(\\d+).*", "$1"));
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

    private static List<Path> archives(Path cache) throws IOException {
        Path dir = cache.resolve("jdem846");
        if (!Files.isDirectory(dir)) {
            return List.of();
        }
        try (Stream<Path> files = Files.list(dir)) {
            return files.filter(f -> f.toString().endsWith(".jsa")).sorted().toList();
        }
    }
}
