package io.github.jdem846.cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeFalse;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import io.github.jdem846.io.DemReader;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.testing.DemTiles;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.BasicFileAttributes;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.stream.Stream;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The bad-input matrix of docs/reliability.md: every writing command (render, hillshade, tint, shadows, tiles)
 * run in-process with an output that is an input (however spelt), an output it cannot write, and options at and
 * beyond their limits. Each case must end with its exit status (1 for input/output failures, 2 for bad usage), one
 * line on stderr that starts with {@code jdem846: } and says what is wrong (plus at most the hint to --help), no
 * stack trace or exception name, nothing on stdout, and every file as it was: no file added, removed or touched, in
 * the input directory or the output directory.
 *
 * <p>Inputs: Big Tujunga as GeoTIFF (with a {@code .prj}, a world file and a {@code .aux.xml} beside it, as GDAL
 * leaves them) and as GridFloat, Jacksboro cut into a mosaic of four GeoTIFF tiles, and a VRT over the GeoTIFF.
 */
class BadInputMatrixTest {

    private static final Path BT = Path.of("testdata/dem/bigtujunga_srtm30m_utm11n");
    private static final List<String> IMAGE_COMMANDS = List.of("render", "hillshade", "tint", "shadows");

    @TempDir
    static Path root;

    private static Map<Path, String> before;

    @BeforeAll
    static void inputs() throws IOException {
        Path in = Files.createDirectories(root.resolve("in"));
        Files.copy(Path.of(BT + ".tif"), in.resolve("dem.tif"));
        Files.copy(Path.of(BT + ".prj"), in.resolve("dem.prj"));
        Files.writeString(in.resolve("dem.tfw"), "30\n0\n0\n-30\n376328.6554542635\n3807902.8276283755\n");
        Files.writeString(in.resolve("dem.tif.aux.xml"), "<PAMDataset><Metadata/></PAMDataset>\n");
        for (String ext : new String[] {"flt", "hdr", "prj"}) {
            Files.copy(Path.of(BT + "." + ext), in.resolve("bt." + ext));
        }
        Files.writeString(in.resolve("notes.txt"), "not a directory");
        Files.createDirectory(in.resolve("x"));
        Files.createSymbolicLink(in.resolve("link.tif"), in.resolve("dem.tif"));
        Files.createSymbolicLink(in.resolve("link.pmtiles"), in.resolve("dem.tif"));
        Dem jacksboro = DemReader.read(Path.of("testdata/dem/jacksboro_srtm3s_wgs84.tif"));
        DemTiles.geoTiff(jacksboro, DemTiles.quarters(403, 344, 200, 170, 1),
                Files.createDirectory(in.resolve("mosaic")), "j", 4326, true);
        Files.writeString(in.resolve("one.vrt"), "<VRTDataset rasterXSize=\"1197\" rasterYSize=\"643\">"
                + "<SRS>" + Files.readString(Path.of(BT + ".prj")).strip() + "</SRS>"
                + "<GeoTransform>376313.6554542635, 30, 0, 3807917.8276283755, 0, -30</GeoTransform>"
                + "<VRTRasterBand dataType=\"Int16\" band=\"1\"><SimpleSource>"
                + "<SourceFilename relativeToVRT=\"1\">dem.tif</SourceFilename><SourceBand>1</SourceBand>"
                + "<SrcRect xOff=\"0\" yOff=\"0\" xSize=\"1197\" ySize=\"643\"/>"
                + "<DstRect xOff=\"0\" yOff=\"0\" xSize=\"1197\" ySize=\"643\"/></SimpleSource>"
                + "</VRTRasterBand></VRTDataset>\n");

        Path drape = Files.createDirectories(in.resolve("drape"));   // images to drape, good and bad
        Files.copy(Path.of("testdata/golden/drape/bigtujunga_crop_table2_utm.png"), drape.resolve("far.png"));
        Files.writeString(drape.resolve("far.pgw"), "30\n0\n0\n-30\n15\n-15\n");   // at (0, 0), far away
        Files.copy(Path.of("testdata/golden/drape/bigtujunga_crop_table2_utm.png"), drape.resolve("bare.png"));
        Files.copy(Path.of("testdata/golden/drape/bigtujunga_crop_table2_utm.png"), drape.resolve("badprj.png"));
        Files.copy(Path.of("testdata/golden/drape/bigtujunga_crop_table2_utm.wld"), drape.resolve("badprj.wld"));
        Files.writeString(drape.resolve("badprj.prj"), "PROJCS[nonsense");
        Files.copy(Path.of("testdata/golden/drape/bigtujunga_crop_table2_utm.wld"), drape.resolve("rot.wld"));
        Files.copy(Path.of("testdata/golden/drape/bigtujunga_crop_table2_utm.png"), drape.resolve("rot.png"));
        Files.writeString(drape.resolve("rot.wld"), "30\n0.5\n0.5\n-30\n388928\n3804302\n");
        Files.writeString(drape.resolve("text.png"), "not a picture");
        Path out = Files.createDirectories(root.resolve("out"));
        Path readOnly = Files.writeString(out.resolve("readonly.png"), "an earlier picture");
        Files.setPosixFilePermissions(readOnly, PosixFilePermissions.fromString("r--r--r--"));
        Files.createDirectory(out.resolve("adir.png"));
        Files.writeString(Files.createDirectory(out.resolve("full")).resolve("keep.txt"), "keep");
        Files.createLink(out.resolve("w.pgw"), in.resolve("dem.tif"));   // the world file of w.png is the DEM
        before = snapshot();
    }

    /** Every file and directory under the root with its size and modification time: a write changes them. */
    private static Map<Path, String> snapshot() throws IOException {
        Map<Path, String> files = new TreeMap<>();
        try (Stream<Path> s = Files.walk(root)) {
            for (Path p : s.toList()) {
                BasicFileAttributes a = Files.readAttributes(p, BasicFileAttributes.class,
                        java.nio.file.LinkOption.NOFOLLOW_LINKS);
                files.put(root.relativize(p), a.isDirectory() ? "dir" : a.size() + " " + a.lastModifiedTime());
            }
        }
        return files;
    }

    /** The inputs are still byte for byte the files they were copied from. */
    @AfterAll
    static void inputsIntact() throws IOException {
        assertArrayEquals(Files.readAllBytes(Path.of(BT + ".tif")), Files.readAllBytes(root.resolve("in/dem.tif")));
        assertArrayEquals(Files.readAllBytes(Path.of(BT + ".flt")), Files.readAllBytes(root.resolve("in/bt.flt")));
        assertArrayEquals(Files.readAllBytes(Path.of(BT + ".prj")), Files.readAllBytes(root.resolve("in/dem.prj")));
    }

    /** One case: the arguments ({@code IN/} and {@code OUT/} stand for the two directories), outcome, words. */
    private static Arguments row(int exit, String args, String... mentions) {
        return Arguments.of(args, exit, List.of(mentions));
    }

    static Stream<Arguments> outputSafety() {
        List<Arguments> rows = new ArrayList<>();
        for (String c : IMAGE_COMMANDS) {
            String dem = c + " IN/dem.tif -q ";
            // the output is an input file, however spelt
            rows.add(row(2, dem + "-o IN/dem.tif", "cannot write", "dem.tif", "it is the input file itself",
                    "choose another output name"));
            rows.add(row(2, dem + "-o IN/link.tif", "link.tif", "it is the input file", "dem.tif (the same file)"));
            rows.add(row(2, c + " IN/link.tif -q -o IN/dem.tif", "dem.tif", "it is the input file", "link.tif"));
            rows.add(row(2, dem + "-o RELATIVE/dem.tif", "dem.tif", "it is the input file"));
            rows.add(row(2, dem + "-o IN/x/../dem.tif", "x/../dem.tif", "it is the input file"));
            rows.add(row(2, c + " IN/bt.flt -q -o IN/bt.flt", "bt.flt", "cannot tell the image format",
                    ".png, .tif, .tiff"));
            // a sidecar of the input
            rows.add(row(2, c + " IN/bt.flt -q -o IN/bt.hdr", "bt.hdr", "cannot tell the image format"));
            rows.add(row(2, dem + "-o IN/dem.prj", "dem.prj", "cannot tell the image format"));
            rows.add(row(2, dem + "-o IN/dem.tfw", "dem.tfw", "cannot tell the image format"));
            rows.add(row(2, dem + "-o IN/dem.tif.aux.xml", "dem.tif.aux.xml", "cannot tell the image format"));
            rows.add(row(2, c + " IN/bt.flt -q --world-file -o IN/bt.png", "bt.prj (a sidecar of",
                    "it is the input file"));
            rows.add(row(2, dem + "--world-file -o IN/dem.png", "dem.prj (a sidecar of",
                    "a sidecar of the input file", "dem.tif"));
            rows.add(row(2, dem + "--world-file -o OUT/w.png", "w.pgw (a sidecar of", "it is the input file",
                    "dem.tif (the same file)"));
            // a member of a mosaic or a VRT
            rows.add(row(2, c + " IN/mosaic -q -o IN/mosaic/j_1.tif", "j_1.tif", "it is the input file itself"));
            rows.add(row(2, c + " IN/mosaic/j_0.tif IN/mosaic/j_1.tif IN/mosaic/j_2.tif IN/mosaic/j_3.tif -q -o "
                    + "IN/mosaic/j_3.tif", "j_3.tif", "it is the input file itself"));
            rows.add(row(2, c + " IN/one.vrt -q -o IN/dem.tif", "dem.tif", "it is the input file itself"));
            // a place that cannot be written
            rows.add(row(1, dem + "-o OUT/nodir/relief.png", "cannot write", "relief.png", "nodir",
                    "does not exist"));
            rows.add(row(1, dem + "-o IN/notes.txt/relief.png", "cannot write", "relief.png", "notes.txt",
                    "is not a directory"));
            rows.add(row(1, dem + "-o OUT/readonly.png", "cannot write", "readonly.png", "read-only"));
            rows.add(row(1, dem + "-o OUT/adir.png", "cannot write", "adir.png", "a directory of that name"));
            // a name that is no image
            rows.add(row(2, dem + "-o OUT/relief.bmp", "--output", "relief.bmp", ".png, .tif, .tiff"));
            rows.add(row(2, dem + "-o OUT/relief", "--output", "relief", ".png, .tif, .tiff"));
            rows.add(row(2, dem + "--cog -o OUT/relief.png", "--cog", "relief.png"));
        }
        String tiles = "tiles IN/dem.tif -q -Z 9 ";
        rows.add(row(2, tiles + "-o IN/dem.tif", "dem.tif", "it is the input file itself"));
        rows.add(row(2, tiles + "-o IN/link.pmtiles", "link.pmtiles", "it is the input file",
                "dem.tif (the same file)"));
        rows.add(row(2, tiles + "-o RELATIVE/dem.tif", "dem.tif", "it is the input file"));
        rows.add(row(2, tiles + "-o IN/dem.prj", "dem.prj", "a sidecar of the input file"));
        rows.add(row(2, "tiles IN/mosaic -q -Z 9 -o IN/mosaic/j_2.tif", "j_2.tif", "it is the input file itself"));
        rows.add(row(2, "tiles IN/one.vrt -q -Z 9 -o IN/dem.tif", "dem.tif", "it is the input file itself"));
        rows.add(row(1, "tiles IN/mosaic -q -Z 9 -o IN/mosaic", "mosaic", "not empty"));
        rows.add(row(1, tiles + "-o IN/notes.txt", "notes.txt", "it is a file, not a directory"));
        rows.add(row(1, tiles + "-o OUT/nodir/tiles", "nodir", "does not exist"));
        rows.add(row(1, tiles + "-o OUT/nodir/relief.pmtiles", "relief.pmtiles", "does not exist"));
        rows.add(row(1, tiles + "-o IN/notes.txt/relief.pmtiles", "relief.pmtiles", "notes.txt"));
        rows.add(row(1, tiles + "-o OUT/full", "full", "not empty"));
        rows.add(row(1, tiles + "-o OUT/adir.png/../full", "full", "not empty"));
        rows.add(row(2, tiles + "-o OUT/relief.mbtiles", "--output", "relief.mbtiles", "not written",
                ".pmtiles"));
        return rows.stream();
    }

    static Stream<Arguments> optionLimits() {
        List<Arguments> rows = new ArrayList<>();
        for (String c : List.of("render", "hillshade", "tint", "shadows", "tiles")) {
            String base = c + " IN/dem.tif -q " + (c.equals("tiles") ? "-o OUT/tiles -Z 9 " : "-o OUT/relief.png ");
            rows.add(row(2, base + "--threads 0", "--threads", "got 0", "1 to 1024"));
            rows.add(row(2, base + "--threads 100000", "--threads", "got 100000", "1 to 1024"));
            rows.add(row(2, base + "--threads 99999999999", "--threads", "'99999999999'", "whole number"));
            rows.add(row(2, base + "--tile-size 0", "--tile-size", "got 0", "16 to 4096"));
            rows.add(row(2, base + "--tile-size 100000", "--tile-size", "got 100000", "16 to 4096"));
            rows.add(row(2, base + "--memory 0", "--memory", "'0'", "above 0"));
            rows.add(row(2, base + "--memory 9999999999t", "--memory", "below 8 EiB"));
            rows.add(row(2, base + "--memory lots", "--memory", "'lots'", "512m or 4g"));
            if (c.equals("tint")) {   // no light
                rows.add(row(2, base + "--sun-azimuth 10", "Unknown option: '--sun-azimuth'"));
            } else {
                rows.add(row(2, base + "--sun-azimuth NaN", "--sun-azimuth", "got NaN", "finite number"));
                rows.add(row(2, base + "--sun-azimuth Infinity", "--sun-azimuth", "got Infinity",
                        "finite number"));
                rows.add(row(2, base + "--sun-elevation Infinity", "--sun-elevation", "got Infinity",
                        "between -90 and 90"));
                rows.add(row(2, base + "--sun-elevation NaN", "--sun-elevation", "got NaN", "between -90 and 90"));
            }
            if (!c.equals("tint") && !c.equals("shadows")) {   // the mask has no hillshade
                rows.add(row(2, base + "--z-factor 1e308", "--z-factor", "got 1.0E308", "≤ 1000000"));
                rows.add(row(2, base + "--z-factor NaN", "--z-factor", "got NaN", "≤ 1000000"));
                rows.add(row(2, base + "--z-factor -Infinity", "--z-factor", "got -Infinity", "> 0"));
            }
            if (c.equals("tiles")) {
                rows.add(row(2, base + "--zoom 23", "--zoom", "0 to 22", "23"));
                rows.add(row(2, base + "--zoom 5-3", "--zoom", "0 to 22", "5-3"));
                rows.add(row(2, base + "--zoom -1", "--zoom", "0 to 22"));
                rows.add(row(2, base + "--zoom 99999999999", "--zoom", "99999999999"));
                rows.add(row(2, base + "--zoom abc", "--zoom", "abc"));
                rows.add(row(2, base + "--png-level 10", "--png-level", "10"));
                rows.add(row(2, base + "--memory 512m", "--memory does not apply to tiles"));
                continue;
            }
            rows.add(row(2, base + "--width 0", "--width", "got 0", "1 to 100000"));
            rows.add(row(2, base + "--width 2000000000", "--width", "got 2000000000", "1 to 100000"));
            rows.add(row(2, base + "--width 99999999999", "--width", "'99999999999'", "whole number"));
            rows.add(row(2, base + "--height 0", "--height", "got 0", "1 to 100000"));
            rows.add(row(2, base + "--height 2000000000", "--height", "got 2000000000", "1 to 100000"));
            rows.add(row(2, base + "--width 100000 --height 100000", "'--width' and '--height'", "2147483639"));
            rows.add(row(2, base + "--scale 1e-9", "--scale", "1.0E-9", "smallest scale"));
            rows.add(row(2, base + "--scale NaN", "--scale", "got NaN", "above 0"));
            rows.add(row(2, base + "--scale 1e9", "--scale", "at most 100000"));
            rows.add(row(2, base + "--window 3,4,1,2", "--window", "west < east and south < north"));
            rows.add(row(2, base + "--window 0,0,1,1", "--window", "does not intersect", "extent"));
            rows.add(row(2, base + "--window cells:1190,0,100,10", "--window", "inside the 1197×643 grid"));
            rows.add(row(2, base + "--window cells:0,0,2147483647,2147483647", "--window",
                    "inside the 1197×643 grid"));
            rows.add(row(2, base + "--window NaN,0,1,1", "--window", "finite"));
        }
        return rows.stream();
    }

    static Stream<Arguments> drapeImages() {
        String render = "render IN/dem.tif -q -o OUT/relief.png --drape IN/";
        String tiles = "tiles IN/dem.tif -q -Z 11 ";
        return Stream.of(
                row(1, render + "drape/missing.tif", "missing.tif", "no such file"),
                row(1, render + "drape", "drape", "is not a file"),
                row(1, render + "notes.txt", "notes.txt", "unknown image type", ".tif"),
                row(1, render + "drape/text.png", "text.png", "not a PNG or JPEG"),
                row(1, render + "dem.tif", "dem.tif", "not an 8-bit picture", "16 bits"),
                row(1, render + "drape/bare.png", "bare.png", "no georeference", ".pgw"),
                row(1, render + "drape/rot.png", "rot.wld", "rotated", "gdalwarp"),
                row(1, render + "drape/badprj.png", "badprj.prj", "not a CRS in WKT"),
                row(1, render + "drape/far.png", "far.png", "does not overlap the picture"),
                row(1, "render IN/bt.flt -q -o OUT/relief.png --drape IN/drape/far.png", "far.png",
                        "does not overlap"),
                row(1, tiles + "-o OUT/tiles --drape IN/drape/missing.tif", "missing.tif", "no such file"),
                row(1, tiles + "-o OUT/relief.pmtiles --drape IN/drape/missing.tif", "missing.tif",
                        "no such file"),
                row(1, tiles + "-o OUT/tiles --drape IN/drape/text.png", "text.png", "not a PNG or JPEG"),
                row(1, tiles + "-o OUT/relief.pmtiles --drape IN/drape/far.png", "far.png",
                        "does not overlap the picture"));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("drapeImages")
    @Timeout(value = 30, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void aDrapeThatCannotBeUsedIsOneLineNamingItAndNoPicture(String args, int exit, List<String> mentions)
            throws IOException {
        assertRefused(args, exit, mentions);
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("outputSafety")
    @Timeout(value = 30, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void anOutputThatIsAnInputOrCannotBeWrittenIsRefusedAndNothingChanges(String args, int exit,
                                                                          List<String> mentions)
            throws IOException {
        assertRefused(args, exit, mentions);
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("optionLimits")
    @Timeout(value = 30, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void anOptionBeyondItsLimitsIsBadUsageNamingTheRange(String args, int exit, List<String> mentions)
            throws IOException {
        assertRefused(args, exit, mentions);
    }

    /** A directory not even the superuser can create files in: Linux's /proc. */
    @Test
    void aDirectoryWhereNoFileCanBeCreatedIsNamed() throws IOException {
        assumeTrue(Files.isDirectory(Path.of("/proc/self")), "Linux /proc");
        assertRefused("render IN/dem.tif -q -o /proc/relief.png", 1,
                List.of("cannot write /proc/relief.png", "cannot create a file in /proc"));
        assertRefused("tiles IN/dem.tif -q -Z 9 -o /proc/relief.pmtiles", 1,
                List.of("cannot write /proc/relief.pmtiles"));
        assertRefused("tiles IN/dem.tif -q -Z 9 -o /proc/tiles", 1, List.of("cannot write /proc/tiles"));
    }

    /** A directory without write permission (skipped for the superuser, who may write there anyway). */
    @Test
    void anUnwritableDirectoryIsNamed() throws IOException {
        Path locked = Files.createDirectories(root.resolve("locked"));
        Files.setPosixFilePermissions(locked, PosixFilePermissions.fromString("r-xr-xr-x"));
        try {
            assumeFalse(Files.isWritable(locked), "the superuser can write anywhere");
            before = snapshot();
            for (String c : IMAGE_COMMANDS) {
                assertRefused(c + " IN/dem.tif -q -o " + locked.resolve("relief.png"), 1,
                        List.of("cannot write", "relief.png", "is not writable"));
            }
            assertRefused("tiles IN/dem.tif -q -Z 9 -o " + locked.resolve("t"), 1, List.of("is not writable"));
        } finally {
            Files.setPosixFilePermissions(locked, PosixFilePermissions.fromString("rwxr-xr-x"));
            Files.delete(locked);
            before = snapshot();
        }
    }

    private static void assertRefused(String template, int exit, List<String> mentions) throws IOException {
        String relative = Path.of("").toAbsolutePath().relativize(root.resolve("in")).toString();
        String[] args = Arrays.stream(template.split(" ")).map(a -> a
                .replace("RELATIVE/", relative + "/")
                .replace("IN/", root.resolve("in") + "/")
                .replace("OUT/", root.resolve("out") + "/")).toArray(String[]::new);
        CliRun run = CliRun.of(args);
        String what = template + " -> " + run.err();
        assertEquals(exit, run.exitCode(), what);
        assertEquals("", run.out(), what);
        List<String> lines = run.err().lines().filter(l -> !l.startsWith("jdem846: note: ")).toList();
        assertFalse(lines.isEmpty(), what);
        String message = lines.get(0);
        assertTrue(message.startsWith("jdem846: "), what);
        assertTrue(lines.size() == 1 || lines.size() == 2 && exit == 2 && lines.get(1).startsWith("Try '"),
                "one line, and for bad usage the hint: " + what);
        assertFalse(run.err().contains("Exception") || run.err().contains("\tat "), "no stack trace: " + what);
        for (String m : mentions) {
            assertTrue(message.contains(m), "mentions '" + m + "': " + what);
        }
        Map<Path, String> after = snapshot();
        List<String> changed = Stream.concat(before.keySet().stream(), after.keySet().stream()).distinct()
                .filter(p -> !java.util.Objects.equals(before.get(p), after.get(p))).map(Path::toString).toList();
        assertEquals(List.of(), changed, "no file added, removed or touched: " + what);
    }
}
