package io.github.jdem846.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code jdem846 view}: a picture of the size asked for; misuse is exit 2 and leaves no file. */
class ViewCommandTest {

    private static final String DEM = "testdata/dem/bigtujunga_srtm30m_utm11n.tif";

    @TempDir
    Path tmp;

    @Test
    void writesAPerspectiveViewOfTheSizeAskedFor() throws Exception {
        Path out = tmp.resolve("view.png");
        CliRun run = CliRun.of("view", DEM, "-o", out.toString(), "-q", "--width", "180", "--height", "120",
                "--camera-azimuth", "150", "--camera-elevation", "40", "--exaggeration", "2", "--shadows", "sweep");
        assertEquals(0, run.exitCode(), run.err());
        BufferedImage image = ImageIO.read(out.toFile());
        assertEquals(180, image.getWidth());
        assertEquals(120, image.getHeight());
        assertTrue(image.getRGB(90, 60) != image.getRGB(0, 0), "terrain in the middle, background in the corner");
    }

    @Test
    void badCameraOptionsAreBadUsage() {
        Path out = tmp.resolve("x.png");
        CliRun low = CliRun.of("view", DEM, "-o", out.toString(), "--camera-elevation", "0");
        assertEquals(2, low.exitCode(), low.err());
        assertTrue(low.err().contains("--camera-elevation"), low.err());
        CliRun fov = CliRun.of("view", DEM, "-o", out.toString(), "--fov", "180");
        assertEquals(2, fov.exitCode(), fov.err());
        assertTrue(fov.err().contains("--fov"), fov.err());
        CliRun scale = CliRun.of("view", DEM, "-o", out.toString(), "--scale", "0.5");
        assertEquals(2, scale.exitCode(), scale.err());
        CliRun worldFile = CliRun.of("view", DEM, "-o", out.toString(), "--world-file");
        assertEquals(2, worldFile.exitCode(), worldFile.err());
        assertFalse(Files.exists(out));
    }

    @Test
    void aMissingFileIsExitOne() {
        Path out = tmp.resolve("x.png");
        CliRun run = CliRun.of("view", tmp.resolve("missing.tif").toString(), "-o", out.toString());
        assertEquals(1, run.exitCode(), run.err());
        assertEquals(1, run.err().strip().lines().count(), run.err());
        assertFalse(Files.exists(out));
    }

    /**
     * A camera 40 m above the floor of Big Tujunga Canyon looking east down the valley: the top row is sky (one
     * gradient colour across), the bottom row terrain (not the sky's colours).
     */
    @Test
    void aCameraByPositionAndLookAtPoint() throws Exception {
        Path out = tmp.resolve("valley.png");
        CliRun run = CliRun.of("view", DEM, "-o", out.toString(), "-q", "--width", "120", "--height", "80",
                "--camera-position", "382479,3796143,560", "--look-at", "384729,3796203", "--fov", "60",
                "--overlay", "testdata/overlay/bigtujunga_test_shapes.geojson:color=yellow,width=3");
        assertEquals(0, run.exitCode(), run.err());
        BufferedImage image = ImageIO.read(out.toFile());
        assertEquals(image.getRGB(0, 0), image.getRGB(119, 0), "sky across the top");
        for (int x = 0; x < 120; x++) {
            assertTrue(image.getRGB(x, 79) != image.getRGB(x, 0), "terrain across the bottom, column " + x);
        }
    }

    @Test
    void badCameraPlacementsAreBadUsage() {
        Path out = tmp.resolve("x.png");
        String[][] cases = {
            {"--camera-position", "382479,3796143,560"},
            {"--look-at", "384729,3796203"},
            {"--camera-position", "382479,3796143", "--look-at", "384729,3796203"},
            {"--camera-position", "382479,3796143,x", "--look-at", "384729,3796203"},
            {"--camera-position", "382479,3796143,560", "--look-at", "1,2,3,4"},
            {"--camera-position", "382479,3796143,560", "--look-at", "384729,3796203", "--camera-azimuth", "10"},
            {"--camera-position", "382479,3796143,560", "--look-at", "382479,3796143,560"},
            {"--overlay", "testdata/overlay/bigtujunga_test_shapes.geojson:width=-1"},
        };
        for (String[] options : cases) {
            String[] args = new String[options.length + 4];
            args[0] = "view";
            args[1] = DEM;
            args[2] = "-o";
            args[3] = out.toString();
            System.arraycopy(options, 0, args, 4, options.length);
            CliRun run = CliRun.of(args);
            assertEquals(2, run.exitCode(), String.join(" ", options) + ": " + run.err());
            assertEquals(1, run.err().strip().lines().filter(l -> !l.startsWith("Try ")).count(), run.err());
            assertTrue(java.util.stream.Stream.of("--camera-position", "--look-at", "--camera-azimuth", "--overlay")
                    .anyMatch(run.err()::contains), "the message names the option: " + run.err());
        }
        CliRun away = CliRun.of("view", DEM, "-o", out.toString(), "--camera-position", "382479,3796143,560",
                "--look-at", "382479,3796143,9000");
        assertEquals(1, away.exitCode(), away.err());
        assertTrue(away.err().contains("sees none of the terrain"), away.err());
        assertFalse(Files.exists(out));
    }
}
