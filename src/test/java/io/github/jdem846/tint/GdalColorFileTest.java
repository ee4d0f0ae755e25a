package io.github.jdem846.tint;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.raster.ElevationStatistics;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class GdalColorFileTest {

    @TempDir
    Path dir;

    private StopRamp read(String text, ColorSelection selection) throws IOException {
        Path file = dir.resolve("relief.txt");
        Files.writeString(file, text, StandardCharsets.ISO_8859_1);
        return ColorRamp.fromGdalColorFile(file, selection);
    }

    private StopRamp read(String text) throws IOException {
        return read(text, ColorSelection.INTERPOLATE);
    }

    private static TintFunction bind(StopRamp ramp, double min, double max) {
        return ramp.bind(new ElevationStatistics(min, max, 1, 1));
    }

    private static int argb(int r, int g, int b, int a) {
        return a << 24 | r << 16 | g << 8 | b;
    }

    @Test
    void separatorsCommentsAndBlankLines() throws IOException {
        StopRamp ramp = read("\uFEFF# comment\n// another\n\n0\t10 ,20:30\r\n100,110,120,130,140\n  200   red\n"
                .replace("\uFEFF", "\u00EF\u00BB\u00BF"));
        assertEquals(List.of(new ColorStop(0, StopUnit.ABSOLUTE, argb(10, 20, 30, 255)),
                new ColorStop(100, StopUnit.ABSOLUTE, argb(110, 120, 130, 140)),
                new ColorStop(200, StopUnit.ABSOLUTE, argb(255, 0, 0, 255))), ramp.stops());
        assertEquals("relief.txt", ramp.name());
        assertEquals(0, ramp.noDataArgb());
    }

    @Test
    void gdaldemNamedColours() throws IOException {
        // gdaldem's table is fractions of 255 truncated: 0.75 → 191, 0.5 → 127, 0.25 → 63.
        String[] names = {"white", "black", "red", "green", "blue", "yellow", "magenta", "cyan", "aqua", "grey",
            "gray", "orange", "brown", "purple", "violet", "indigo"};
        int[] expected = {0xFFFFFF, 0x000000, 0xFF0000, 0x00FF00, 0x0000FF, 0xFFFF00, 0xFF00FF, 0x00FFFF, 0x00BFBF,
            0xBFBFBF, 0xBFBFBF, 0xFF7F00, 0xBF7F3F, 0x7F00FF, 0x7F00FF, 0x007FFF};
        StringBuilder text = new StringBuilder();
        for (int i = 0; i < names.length; i++) {
            text.append(i).append(' ').append(i % 2 == 0 ? names[i] : names[i].toUpperCase()).append('\n');
        }
        text.append("16 indigo 100\n");
        TintFunction tint = bind(read(text.toString()), 0, 16);
        for (int i = 0; i < names.length; i++) {
            assertEquals(0xFF000000 | expected[i], tint.argb(i), names[i]);
        }
        assertEquals(argb(0, 127, 255, 100), tint.argb(16));
    }

    @Test
    void percentNoDataAndMixedUnits() throws IOException {
        StopRamp ramp = read("nv 1 2 3 4\n0% 0 0 0\n150 100 100 100\n100% 200 200 200\n");
        TintFunction tint = bind(ramp, 100, 300);
        assertEquals(argb(1, 2, 3, 4), tint.argb(Float.NaN));
        assertEquals(argb(0, 0, 0, 255), tint.argb(100));
        assertEquals(argb(50, 50, 50, 255), tint.argb(125));       // 0 + 25/50·100
        assertEquals(argb(100, 100, 100, 255), tint.argb(150));
        assertEquals(argb(150, 150, 150, 255), tint.argb(225));    // 100 + 75/150·100
        assertEquals(argb(200, 200, 200, 255), tint.argb(1e6f));
        assertEquals(argb(0, 0, 0, 255), tint.argb(-1e6f));
    }

    @Test
    void interpolatesAlphaAndRoundsHalfUp() throws IOException {
        TintFunction tint = bind(read("0 0 0 0 0\n100 255 255 255 255\n"), 0, 100);
        // 0.2·2.55 = 0.51 → 1 (GDAL 3.6.2's +0.45 gave 0); 50·2.55 = 127.5 → 128 (3.6.2: 127).
        assertEquals(argb(1, 1, 1, 1), tint.argb(0.2f));
        assertEquals(argb(128, 128, 128, 128), tint.argb(50));
    }

    @Test
    void nearestGivesTiesToTheUpperStop() throws IOException {
        TintFunction tint = bind(read("0 10 20 30\n100 110 120 130\n200 210 220 230\n", ColorSelection.NEAREST),
                0, 200);
        assertEquals(argb(10, 20, 30, 255), tint.argb(-5));
        assertEquals(argb(10, 20, 30, 255), tint.argb(49.9f));
        assertEquals(argb(110, 120, 130, 255), tint.argb(50));
        assertEquals(argb(110, 120, 130, 255), tint.argb(100.5f));
        assertEquals(argb(210, 220, 230, 255), tint.argb(150));
        assertEquals(argb(210, 220, 230, 255), tint.argb(300));
    }

    @Test
    void exactColoursOnlyTheStops() throws IOException {
        TintFunction tint = bind(read("nv 1 2 3 4\n0 10 20 30\n100 110 120 130\n200 210 220 230\n",
                ColorSelection.EXACT), 0, 200);
        assertEquals(argb(10, 20, 30, 255), tint.argb(0));
        assertEquals(argb(110, 120, 130, 255), tint.argb(100));   // GDAL 3.6.2 wrongly gave 0 here
        assertEquals(argb(210, 220, 230, 255), tint.argb(200));
        assertEquals(argb(1, 2, 3, 4), tint.argb(Float.NaN));
        for (float e : new float[] {-5, 99.5f, 100.5f, 150, 300}) {
            assertEquals(0, tint.argb(e), "at " + e);
        }
    }

    @Test
    void aHardStepUsesTheFirstListedColourOnTheStep() throws IOException {
        TintFunction tint = bind(read("0 0 0 0\n5 10 20 30\n5 200 210 220\n10 255 255 255\n"), 0, 10);
        assertEquals(argb(10, 20, 30, 255), tint.argb(5));
        assertEquals(argb(10, 20, 30, 255), tint.argb(Math.nextDown(5f)));
        assertEquals(argb(200, 210, 220, 255), tint.argb(Math.nextUp(5f)));
        assertEquals(argb(5, 10, 15, 255), tint.argb(2.5f));
        assertEquals(argb(228, 233, 238, 255), tint.argb(7.5f));   // 200 + 0.5·55 = 227.5 → 228
    }

    @Test
    void gmtPalette() throws IOException {
        StopRamp ramp = read("# COLOR_MODEL = RGB\n-100 0 0 255 0 0 255 255\n0 0 128 0 100 255 255 255\n"
                + "B 0 0 0\nF 255 255 255\nN 128 128 128\n");
        TintFunction tint = bind(ramp, -100, 100);
        assertEquals(argb(0, 0, 255, 255), tint.argb(-100));
        // Slice 1 runs from (0,0,255) at −100 to (0,255,255) at 0: −50 → (0, 127.5, 255) → (0, 128, 255).
        assertEquals(argb(0, 128, 255, 255), tint.argb(-50));
        assertEquals(argb(0, 255, 255, 255), tint.argb(0));       // the first listed of the two stops at 0
        assertEquals(argb(0, 128, 0, 255), tint.argb(Math.nextUp(0f)));
        assertEquals(argb(128, 192, 128, 255), tint.argb(50));    // (0,128,0) → (255,255,255): 127.5, 191.5
        assertEquals(argb(128, 128, 128, 255), tint.argb(Float.NaN));
        assertEquals(4, ramp.stops().size());
    }

    // --- errors ---------------------------------------------------------------------------------------------

    private void assertError(String text, String... fragments) {
        ColorFileException e = assertThrows(ColorFileException.class, () -> read(text));
        assertTrue(e.getMessage().startsWith(dir.resolve("relief.txt").toString()), e.getMessage());
        for (String fragment : fragments) {
            assertTrue(e.getMessage().contains(fragment), "'" + fragment + "' missing from: " + e.getMessage());
        }
    }

    @Test
    void badFilesNameTheLineAndTheProblem() {
        assertError("0 0 0 0\n# c\n150% 1 2 3\n", "line 3", "between 0% and 100%", "150%");
        assertError("0 0 0 0\n100 purpleish\n", "line 2", "unknown colour name 'purpleish'", "indigo", "R G B");
        assertError("abc 1 2 3\n", "line 1", "elevation 'abc' is not a number");
        assertError("1e999 1 2 3\n", "line 1", "out of range");
        assertError("100 1 2 300\n", "line 1", "blue must lie between 0 and 255, got 300");
        assertError("100 1 2 3.5\n", "line 1", "blue '3.5' is not an integer");
        assertError("100 1 2 3 # note\n", "line 1", "alpha '#'", "own line");
        assertError("100 1 2\n", "line 1", "three colour components");
        assertError("100\n", "line 1", "only '100'");
        assertError("nv 0 0 0 0\n0 red\nnv white\n", "line 3", "given twice", "line 1");
        assertError("# nothing\n\n", "no colour entries");
        assertError("nv 0 0 0 0\n", "no colour entries");
        assertError("# COLOR_MODEL = HSV\n0 0 0 0 1 1 1 1\n", "line 1", "COLOR_MODEL = RGB");
        assertError("# COLOR_MODEL = RGB\n0 0 0 0 1 1 1\n", "line 2", "8 fields");
    }

    @Test
    void theExampleInTheDocsIsValid() throws IOException {
        String doc = Files.readString(Path.of("docs", "tint.md"));
        int start = doc.indexOf("```\n# A comment line") + 4;
        StopRamp ramp = read(doc.substring(start, doc.indexOf("```", start)));
        assertEquals(4, ramp.stops().size());
        assertEquals(0, ramp.noDataArgb());
        assertEquals(argb(255, 0, 0, 128), ramp.stops().get(3).argb());
    }

    @Test
    void missingFileIsAnIoError() {
        assertThrows(java.nio.file.NoSuchFileException.class,
                () -> ColorRamp.fromGdalColorFile(dir.resolve("absent.txt"), ColorSelection.INTERPOLATE));
    }
}
