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

/** {@code render --projection}: a georeferenced picture in the projection, and one clear line for bad values. */
class ProjectionOptionsTest {

    private static final String LUXEMBOURG = "testdata/dem/luxembourg_srtm30s_wgs84.tif";
    private static final String JACKSBORO = "testdata/dem/jacksboro_srtm3s_wgs84.tif";
    private static final String BIG_TUJUNGA = "testdata/dem/bigtujunga_srtm30m_utm11n.tif";

    @TempDir
    Path dir;

    @Test
    void robinsonPictureWithItsWkt() throws Exception {
        Path out = dir.resolve("lux.png");
        CliRun run = CliRun.of("render", LUXEMBOURG, "--projection", "robinson", "-o", out.toString(), "--width",
                "120", "--world-file", "-q", "--threads=2");
        assertEquals(0, run.exitCode(), run.err());
        BufferedImage image = ImageIO.read(out.toFile());
        assertEquals(120, image.getWidth());
        // Luxembourg spans 0.79° × 0.75° at 50°N: taller than wide in Robinson, as on the ground
        assertTrue(image.getHeight() > 100 && image.getHeight() < 160, "height " + image.getHeight());
        assertEquals(0, image.getRGB(0, 0) >>> 24, "outside the border is transparent");
        assertEquals(255, image.getRGB(60, 70) >>> 24, "the middle of the country is opaque");
        String prj = Files.readString(dir.resolve("lux.prj"));
        assertTrue(prj.contains("PROJECTION[\"Robinson\"]") && prj.contains("WGS 84"), prj);
        String world = Files.readString(dir.resolve("lux.pgw"));
        double west = Double.parseDouble(world.lines().toList().get(4));
        assertTrue(west > 0.8487 * 6378137 * 0.8679 * Math.toRadians(5.7) && west < 0.8487 * 6378137 * Math.toRadians(
                5.8), "west pixel centre " + west);
    }

    @Test
    void epsgCodeToGeoTiffFromAProjectedDem() throws Exception {
        Path out = dir.resolve("bt.tif");
        CliRun run = CliRun.of("render", BIG_TUJUNGA, "--projection", "EPSG:3395", "-o", out.toString(), "--width",
                "200", "-q", "--threads=2");
        assertEquals(0, run.exitCode(), run.err());
        assertFalse(run.err().contains("without an EPSG code"), run.err());
        assertTrue(Files.size(out) > 1000);
    }

    /** The gray products in a projection: georeferenced, no-data 0 outside a hillshade, the same under --memory. */
    @Test
    void grayProductsAreProjectedToo() throws Exception {
        Path hillshade = dir.resolve("hs.tif");
        CliRun run = CliRun.of("hillshade", LUXEMBOURG, "--projection", "winkel-tripel", "-o", hillshade.toString(),
                "--width", "150", "--world-file", "-q", "--threads=2");
        assertEquals(0, run.exitCode(), run.err());
        BufferedImage image = ImageIO.read(hillshade.toFile());
        assertEquals(150, image.getWidth());
        assertEquals(1, image.getRaster().getNumBands());
        assertEquals(0, image.getRaster().getSample(0, 0, 0), "no-data outside the country");
        int middle = image.getRaster().getSample(75, image.getHeight() / 2, 0);
        assertTrue(middle > 0, "the middle is shaded: " + middle);
        String prj = Files.readString(dir.resolve("hs.prj"));
        assertTrue(prj.contains("PROJECTION[\"Winkel_Tripel\"]"), prj);
        Path banded = dir.resolve("hs-banded.tif");
        CliRun whole = CliRun.of("hillshade", JACKSBORO, "--projection", "winkel-tripel", "-o",
                hillshade.toString(), "--width", "150", "--world-file", "-q", "--threads=2");
        assertEquals(0, whole.exitCode(), whole.err());
        CliRun small = CliRun.of("hillshade", JACKSBORO, "--projection", "winkel-tripel", "-o", banded.toString(),
                "--width", "150", "--world-file", "--memory", "400k", "--threads=2");
        assertEquals(0, small.exitCode(), small.err());
        assertTrue(small.err().contains("warping it in bands"), small.err());
        assertEquals(-1, Files.mismatch(hillshade, banded), "the same file in bands");
        for (String command : new String[] {"shadows", "skyview", "tint"}) {
            Path out = dir.resolve(command + ".png");
            CliRun r = CliRun.of(command, LUXEMBOURG, "--projection", "mollweide", "-o", out.toString(), "--width",
                    "100", "-q", "--threads=2");
            assertEquals(0, r.exitCode(), command + ": " + r.err());
            assertEquals(command.equals("tint") ? 4 : 1, ImageIO.read(out.toFile()).getRaster().getNumBands(),
                    command);
        }
    }

    @Test
    void badValuesAreOneLineOfUsage() {
        String out = dir.resolve("x.png").toString();
        CliRun unknown = CliRun.of("render", LUXEMBOURG, "--projection", "gnomonic", "-o", out, "-q");
        assertEquals(2, unknown.exitCode(), unknown.err());
        assertTrue(unknown.err().startsWith("jdem846: ") && unknown.err().contains("robinson"), unknown.err());
        CliRun offline = CliRun.of("render", LUXEMBOURG, "--projection", "EPSG:3035", "-o", out, "-q");
        assertEquals(2, offline.exitCode(), offline.err());
        assertTrue(offline.err().contains("EPSG:3035") && offline.err().contains(".prj"), offline.err());
        CliRun meridian = CliRun.of("render", LUXEMBOURG, "--central-meridian", "10", "-o", out, "-q");
        assertEquals(2, meridian.exitCode(), meridian.err());
        assertTrue(meridian.err().contains("--central-meridian needs --projection"), meridian.err());
        // EPSG:2193 is not known to Apache SIS offline: one line naming the file; the same grid with its .prj works
        String volcano = "testdata/dem/maungawhau-volcano_10m_nztm-approx";
        CliRun nztm = CliRun.of("render", volcano + ".tif", "--projection", "robinson", "-o", out, "-q");
        assertEquals(1, nztm.exitCode(), nztm.err());
        assertTrue(nztm.err().startsWith("jdem846: " + volcano + ".tif: ") && nztm.err().contains("WKT"),
                nztm.err());
        assertEquals(1, nztm.err().strip().lines().count(), nztm.err());
        CliRun withPrj = CliRun.of("render", volcano + ".flt", "--projection", "robinson", "-o",
                dir.resolve("v.png").toString(), "-q");
        assertEquals(0, withPrj.exitCode(), withPrj.err());
        for (CliRun r : new CliRun[] {unknown, offline, meridian, nztm}) {
            assertFalse(r.err().contains("\tat "), r.err());
        }
        assertFalse(Files.exists(dir.resolve("x.png")));
    }
}
