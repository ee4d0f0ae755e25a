package io.github.jdem846.cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * An output that is one of the input's files (the DEM, its .hdr or .prj), however spelt, is refused before any
 * work with exit status 2 and one line naming both; the input's files stay byte for byte as they were and no
 * other file appears.
 */
class OutputOverInputTest {

    private static final Path TIF = Path.of("testdata/dem/maungawhau-volcano_10m_nztm-approx.tif");
    private static final String FLT_STEM = "testdata/dem/maungawhau-volcano_10m_nztm-approx";

    @TempDir
    Path tmp;

    private Path copyTif() throws IOException {
        return Files.copy(TIF, tmp.resolve("dem.tif"));
    }

    private Path copyGridFloat() throws IOException {
        for (String ext : new String[] {"flt", "hdr", "prj"}) {
            Files.copy(Path.of(FLT_STEM + "." + ext), tmp.resolve("lux." + ext));
        }
        return tmp.resolve("lux.flt");
    }

    private Map<Path, byte[]> snapshot() throws IOException {
        Map<Path, byte[]> files = new LinkedHashMap<>();
        try (Stream<Path> s = Files.walk(tmp)) {
            for (Path p : s.filter(Files::isRegularFile).sorted().toList()) {
                files.put(p, Files.readAllBytes(p));
            }
        }
        return files;
    }

    /** Runs the command, expects exit 2 with one line naming {@code named}, and every file unchanged. */
    private void assertRefused(String named, String... args) throws IOException {
        Map<Path, byte[]> before = snapshot();
        CliRun run = CliRun.of(args);
        assertEquals(2, run.exitCode(), String.join(" ", args) + " -> " + run.err());
        String err = run.err().strip();
        assertEquals(1, err.lines().count(), "one line: " + err);
        assertTrue(err.startsWith("jdem846: cannot write "), err);
        assertTrue(err.contains(named), "names " + named + ": " + err);
        assertTrue(err.contains("choose another output name"), err);
        assertFalse(err.contains("Exception"), err);
        Map<Path, byte[]> after = snapshot();
        assertEquals(before.keySet(), after.keySet(), "no file added or removed");
        for (Map.Entry<Path, byte[]> e : before.entrySet()) {
            assertArrayEquals(e.getValue(), after.get(e.getKey()), e.getKey() + " unchanged");
        }
    }

    @ParameterizedTest
    @ValueSource(strings = {"render", "hillshade", "tint", "shadows"})
    void outputEqualToTheInputIsRefused(String command) throws IOException {
        Path dem = copyTif();
        assertRefused("dem.tif", command, dem.toString(), "-o", dem.toString(), "-q");
    }

    @Test
    void otherSpellingsOfTheSameFileAreRefused() throws IOException {
        Path dem = copyTif();
        Files.createDirectory(tmp.resolve("x"));
        Path dotDot = tmp.resolve("x").resolve("..").resolve("dem.tif");
        assertRefused("dem.tif", "render", dem.toString(), "-o", dotDot.toString(), "-q");

        Path symlink = Files.createSymbolicLink(tmp.resolve("link.tif"), dem);
        assertRefused("link.tif", "hillshade", dem.toString(), "-o", symlink.toString(), "-q");
        assertRefused("dem.tif", "hillshade", symlink.toString(), "-o", dem.toString(), "-q");

        Path hardLink = Files.createLink(tmp.resolve("hard.tif"), dem);
        assertRefused("hard.tif", "shadows", dem.toString(), "-o", hardLink.toString(), "-q");
    }

    @Test
    void aGridFloatOrItsHeaderAsOutputIsRefused() throws IOException {
        Path flt = copyGridFloat();
        Path tif = tmp.resolve("lux.tif");
        Files.createLink(tif, tmp.resolve("lux.prj"));   // a .tif name that is the .prj
        assertRefused("lux.prj", "hillshade", flt.toString(), "-o", tif.toString(), "-q");
        assertRefused("lux.prj", "hillshade", tmp.resolve("lux.hdr").toString(), "-o", tif.toString(), "-q");
    }

    @ParameterizedTest
    @ValueSource(strings = {"png", "tif"})
    void worldFileSidecarsNeverReplaceTheInputsPrj(String ext) throws IOException {
        Path flt = copyGridFloat();
        Path out = tmp.resolve("lux." + ext);
        assertRefused("lux.prj", "render", flt.toString(), "-o", out.toString(), "--world-file", "-q");
        assertRefused("lux.prj", "hillshade", flt.toString(), "-o", out.toString(), "--world-file", "-q");
    }

    @Test
    void anAsciiGridsPrjIsProtectedToo() throws IOException {
        Path asc = Files.copy(Path.of("testdata/formats/luxembourg.asc"), tmp.resolve("grid.asc"));
        Files.copy(Path.of(FLT_STEM + ".prj"), tmp.resolve("grid.prj"));
        assertRefused("grid.prj", "tint", asc.toString(), "-o", tmp.resolve("grid.png").toString(),
                "--world-file", "-q");
    }

    @Test
    void distinctNamesAreWrittenAndTheInputKeptIntact() throws IOException {
        Path flt = copyGridFloat();
        Map<Path, byte[]> before = snapshot();
        Path out = tmp.resolve("relief.png");
        CliRun run = CliRun.of("render", flt.toString(), "-o", out.toString(), "--world-file", "-q");
        assertEquals(0, run.exitCode(), run.err());
        List<Path> written = new ArrayList<>(snapshot().keySet());
        written.removeAll(before.keySet());
        assertEquals(Stream.of("relief.png", "relief.png.aux.xml", "relief.pgw", "relief.prj").map(tmp::resolve)
                .sorted().toList(), written.stream().sorted().toList());
        for (Map.Entry<Path, byte[]> e : before.entrySet()) {
            assertArrayEquals(e.getValue(), Files.readAllBytes(e.getKey()), e.getKey() + " unchanged");
        }
        // without --world-file, lux.png beside lux.flt touches no sidecar: allowed
        CliRun plain = CliRun.of("hillshade", flt.toString(), "-o", tmp.resolve("lux.png").toString(), "-q");
        assertEquals(0, plain.exitCode(), plain.err());
        assertArrayEquals(before.get(tmp.resolve("lux.prj")), Files.readAllBytes(tmp.resolve("lux.prj")));
    }
}
