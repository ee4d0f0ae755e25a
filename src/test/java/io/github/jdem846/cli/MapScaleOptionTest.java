package io.github.jdem846.cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code --map-scale}: a Web Mercator DEM is measured on the ground unless it is given, which draws the map metres
 * gdaldem uses; a given {@code --xy-scale} sets the hillshade's cell size either way; one note says what is done.
 */
class MapScaleOptionTest {

    private static final String VANCOUVER = "testdata/dem/vancouver-island_topobathy_2min_mercator";
    private static final String GROUND_NOTE = "jdem846: note: Web Mercator grid: ";

    @TempDir
    Path dir;

    /** Runs the arguments with {@code -o NAME}, asserts success and returns the file's bytes and stderr. */
    private Written write(String name, String... args) throws IOException {
        Path out = dir.resolve(name);
        String[] all = Arrays.copyOf(args, args.length + 4);
        all[args.length] = "-o";
        all[args.length + 1] = out.toString();
        all[args.length + 2] = "-q";
        all[args.length + 3] = "--threads=2";
        CliRun run = CliRun.of(all);
        assertEquals(0, run.exitCode(), String.join(" ", all) + "\n" + run.err());
        return new Written(Files.readAllBytes(out), run.err());
    }

    private record Written(byte[] bytes, String err) {
    }

    @Test
    void hillshadeOnTheGroundByDefaultAndInMapMetresOnRequest() throws IOException {
        Written ground = write("g.png", "hillshade", VANCOUVER + ".tif");
        Written map = write("m.png", "hillshade", VANCOUVER + ".tif", "--map-scale");
        Written one = write("s1.png", "hillshade", VANCOUVER + ".tif", "-s", "1");
        Written oneOnMap = write("s1m.png", "hillshade", VANCOUVER + ".tif", "-s", "1", "--map-scale");
        assertTrue(ground.err().contains(GROUND_NOTE + "slopes use the cells' ground size, row by row"),
                ground.err());
        assertFalse(ground.err().contains("gentler"), ground.err());
        assertFalse(Arrays.equals(ground.bytes(), map.bytes()), "ground and map metres shade differently");
        // map metres are the nominal size, xy-scale 1; a given xy-scale wins over the default and the option
        assertArrayEquals(map.bytes(), one.bytes());
        assertArrayEquals(map.bytes(), oneOnMap.bytes());
        for (Written w : new Written[] {map, one, oneOnMap}) {
            assertFalse(w.err().contains("Web Mercator"), w.err());
        }
    }

    @Test
    void shadowsAndReliefOfTheGridFloatToo() throws IOException {
        // the GridFloat's .prj is ESRI's WKT of Web Mercator, without an EPSG code
        String[] shadows = {"shadows", VANCOUVER + ".flt", "--sun-azimuth", "300", "--sun-elevation", "6"};
        Written ground = write("sg.png", shadows);
        Written map = write("sm.png", append(shadows, "--map-scale"));
        assertTrue(ground.err().contains(GROUND_NOTE + "shadow lengths use"), ground.err());
        assertFalse(map.err().contains("Web Mercator"), map.err());
        assertTrue(shadowed(ground.bytes()) > shadowed(map.bytes()), "longer shadows on the ground");

        String[] relief = {"render", VANCOUVER + ".flt", "--shadows", "sweep", "--sun-elevation", "6"};
        Written reliefGround = write("rg.png", relief);
        Written reliefMap = write("rm.png", append(relief, "--map-scale"));
        assertTrue(reliefGround.err().contains(GROUND_NOTE + "slopes and shadow lengths use"), reliefGround.err());
        assertFalse(Arrays.equals(reliefGround.bytes(), reliefMap.bytes()));
    }

    @Test
    void infoSaysHowRenderingMeasuresTheCellsAndTilesHaveNoSuchOption() {
        CliRun info = CliRun.of("info", VANCOUVER + ".flt");
        assertEquals(0, info.exitCode(), info.err());
        assertTrue(info.out().contains("Notice:         Web Mercator grid: slopes and shadow lengths use the cells' "
                + "ground size"), info.out());
        CliRun tiles = CliRun.of("tiles", VANCOUVER + ".tif", "--zoom", "5", "-o", dir.resolve("t").toString(),
                "--map-scale");
        assertEquals(2, tiles.exitCode(), tiles.err());
        assertTrue(tiles.err().contains("--map-scale"), tiles.err());
    }

    private static String[] append(String[] args, String more) {
        String[] all = Arrays.copyOf(args, args.length + 1);
        all[args.length] = more;
        return all;
    }

    /** Pixels of a gray PNG above 127. */
    private static int shadowed(byte[] png) throws IOException {
        java.awt.image.BufferedImage img = javax.imageio.ImageIO.read(new java.io.ByteArrayInputStream(png));
        int n = 0;
        for (int y = 0; y < img.getHeight(); y++) {
            for (int x = 0; x < img.getWidth(); x++) {
                n += img.getRaster().getSample(x, y, 0) > 127 ? 1 : 0;
            }
        }
        return n;
    }
}
