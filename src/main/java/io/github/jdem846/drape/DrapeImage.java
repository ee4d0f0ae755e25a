package io.github.jdem846.drape;

import com.twelvemonkeys.imageio.plugins.tiff.TIFFImageReaderSpi;
import io.github.jdem846.geo.CrsInfo;
import io.github.jdem846.geo.CrsResolver;
import io.github.jdem846.io.DemFormatException;
import io.github.jdem846.io.esri.SidecarCrs;
import io.github.jdem846.io.geotiff.GeoTiffImageTags;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.raster.PixelAnchor;
import java.awt.Rectangle;
import java.awt.image.BufferedImage;
import java.awt.image.ColorModel;
import java.awt.image.IndexColorModel;
import java.awt.image.Raster;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Iterator;
import java.util.Locale;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.imageio.ImageIO;
import javax.imageio.ImageReadParam;
import javax.imageio.ImageReader;
import javax.imageio.ImageTypeSpecifier;
import javax.imageio.stream.FileImageInputStream;
import javax.imageio.stream.ImageInputStream;

/**
 * A georeferenced picture to drape over a relief, as opened: its file, the grid of its pixels in its CRS, and
 * whether that CRS was given. Read from
 * <ul>
 *   <li>a GeoTIFF of 8-bit samples, gray, gray and alpha, RGB or RGBA (or a palette), placed by its tags (read as a
 *   DEM's are) or else by a world file ({@code .tfw}, {@code .tifw}, {@code .wld});</li>
 *   <li>a PNG or JPEG placed by its world file ({@code .pgw}/{@code .pngw}, {@code .jgw}/{@code .jpgw}, or
 *   {@code .wld}), its CRS from a {@code .prj} or GDAL's {@code .aux.xml} beside it (as {@code render
 *   --world-file} writes them).</li>
 * </ul>
 * An image whose file gives no CRS is taken to be in the CRS of the DEM it is draped on. Only north-up images are
 * read (no rotation terms). Pixels are decoded on demand, only the rows asked for ({@link #readArgb}).
 *
 * @param file     the image file
 * @param grid     its pixels' grid: size, corner origin, pixel size and CRS
 * @param crsGiven true when the file or its sidecars name a CRS; false: it is the DEM's
 */
public record DrapeImage(Path file, GridGeometry grid, boolean crsGiven) {

    private static final Pattern SRS = Pattern.compile("<SRS[^>]*>(.*?)</SRS>", Pattern.DOTALL);

    /**
     * Checks that the parts are given.
     *
     * @param file     the image file
     * @param grid     its pixels' grid: size, corner origin, pixel size and CRS
     * @param crsGiven true when the file or its sidecars name a CRS; false: it is the DEM's
     */
    public DrapeImage {
        java.util.Objects.requireNonNull(file, "file");
        java.util.Objects.requireNonNull(grid, "grid");
    }

    /**
     * Opens an image: reads its header and georeference, no pixels.
     *
     * @param file a GeoTIFF, or a PNG or JPEG with a world file
     * @return the image
     * @throws DrapeFileException when the file is missing, not an image this reads, not 8-bit, or not placed on the
     *                            ground; the message names the file and says what would do
     */
    public static DrapeImage open(Path file) throws DrapeFileException {
        if (!Files.isRegularFile(file)) {
            throw new DrapeFileException(file, Files.exists(file) ? "is not a file" : "no such file");
        }
        String ext = SidecarCrs.extension(file);
        try {
            if (ext.equals("tif") || ext.equals("tiff")) {
                return openTiff(file);
            }
            if (ext.equals("png") || ext.equals("jpg") || ext.equals("jpeg")) {
                return openWithWorldFile(file, ext);
            }
        } catch (DrapeFileException e) {
            throw e;
        } catch (IOException | RuntimeException e) {
            throw new DrapeFileException(file, "not a readable " + ext.toUpperCase(Locale.ROOT) + " image ("
                    + (e.getMessage() == null ? e.getClass().getSimpleName() : e.getMessage()) + ")", e);
        }
        throw new DrapeFileException(file, "unknown image type; expected a GeoTIFF (.tif) or a PNG or JPEG (.png,"
                + " .jpg) with a world file");
    }

    private static DrapeImage openTiff(Path file) throws IOException {
        ImageReader reader = new TIFFImageReaderSpi().createReaderInstance();
        try (ImageInputStream in = new FileImageInputStream(file.toFile())) {
            reader.setInput(in, true, false);
            if (reader.getNumImages(true) < 1) {
                throw new DrapeFileException(file, "the TIFF holds no image");
            }
            int width = reader.getWidth(0);
            int height = reader.getHeight(0);
            GeoTiffImageTags tags;
            try {
                tags = GeoTiffImageTags.read(file, reader.getImageMetadata(0), width, height);
            } catch (DemFormatException e) {
                throw new DrapeFileException(file, e.getMessage().substring(file.toString().length() + 2));
            }
            boolean photometricOk = tags.photometric() == 1 || tags.photometric() == 2 || tags.photometric() == 3
                    || tags.photometric() == 6;
            if (tags.bitsPerSample() != 8 || tags.samplesPerPixel() > 4 || !photometricOk) {
                throw new DrapeFileException(file, "not an 8-bit picture (" + tags.samplesPerPixel() + " sample(s) of "
                        + tags.bitsPerSample() + " bits, PhotometricInterpretation " + tags.photometric()
                        + "); a drape is 8-bit gray, RGB or RGBA, e.g. made by gdaldem color-relief (a DEM is the"
                        + " input, not a drape)");
            }
            if (tags.geometry() == null) {
                GridGeometry fromWorld = worldFileGrid(file, width, height, new String[] {"tfw", "tifw", "wld"});
                if (fromWorld == null) {
                    throw new DrapeFileException(file, "no georeference: no ModelPixelScale and ModelTiepoint or"
                            + " ModelTransformation tags and no world file (.tfw) beside it; georeference it, e.g."
                            + " gdal_translate -a_ullr or gdalwarp");
                }
                return withSidecarCrs(file, fromWorld);
            }
            CrsInfo crs = tags.geometry().crs();
            if (crs.kind() == CrsInfo.Kind.UNKNOWN && crs.sisCrs() == null || crs.assumed()) {
                return withSidecarCrs(file, tags.geometry().withCrs(CrsInfo.UNKNOWN));
            }
            return new DrapeImage(file, tags.geometry(), true);
        } finally {
            reader.dispose();
        }
    }

    private static DrapeImage openWithWorldFile(Path file, String ext) throws IOException {
        int width;
        int height;
        ImageReader reader = readerOf(file);
        try (ImageInputStream in = new FileImageInputStream(file.toFile())) {
            reader.setInput(in, true, true);
            width = reader.getWidth(0);
            height = reader.getHeight(0);
            ImageTypeSpecifier type = reader.getRawImageType(0);
            if (type == null) {
                Iterator<ImageTypeSpecifier> types = reader.getImageTypes(0);
                type = types.hasNext() ? types.next() : null;
            }
            if (type != null && !eightBit(type.getColorModel())) {
                throw new DrapeFileException(file, "not an 8-bit picture (" + type.getColorModel().getPixelSize()
                        + " bits per pixel in " + type.getColorModel().getNumComponents() + " components); a drape is"
                        + " 8-bit gray, RGB or RGBA");
            }
        } finally {
            reader.dispose();
        }
        String first = ext.substring(0, 1) + ext.substring(ext.length() - 1) + "w";
        GridGeometry grid = worldFileGrid(file, width, height, new String[] {first, ext + "w", "wld"});
        if (grid == null) {
            throw new DrapeFileException(file, "no georeference: no world file (." + first + ", ." + ext + "w or"
                    + " .wld) beside it; write one (gdal_translate -co WORLDFILE=YES, or render --world-file) or use"
                    + " a GeoTIFF");
        }
        return withSidecarCrs(file, grid);
    }

    /** The image reader for a PNG or JPEG, found by the file's content. */
    private static ImageReader readerOf(Path file) throws IOException {
        try (ImageInputStream in = new FileImageInputStream(file.toFile())) {
            Iterator<ImageReader> readers = ImageIO.getImageReaders(in);
            while (readers.hasNext()) {
                ImageReader r = readers.next();
                String format = r.getFormatName().toLowerCase(Locale.ROOT);
                if (format.equals("png") || format.startsWith("jp")) {
                    return r;
                }
            }
        }
        throw new DrapeFileException(file, "not a PNG or JPEG image (its content is not recognised)");
    }

    private static boolean eightBit(ColorModel cm) {
        if (cm instanceof IndexColorModel) {
            return true;
        }
        for (int i = 0; i < cm.getNumComponents(); i++) {
            if (cm.getComponentSize(i) != 8) {
                return false;
            }
        }
        return cm.getNumComponents() <= 4;
    }

    /**
     * The grid from the first world file found among {@code extensions}, or null when there is none.
     */
    private static GridGeometry worldFileGrid(Path file, int width, int height, String[] extensions)
            throws IOException {
        for (String e : extensions) {
            Path world = SidecarCrs.sibling(file, e);
            if (Files.isRegularFile(world)) {
                return parseWorldFile(world, width, height);
            }
        }
        return null;
    }

    /** A north-up grid from a world file's six numbers A, D, B, E, C, F (C, F: the upper-left pixel's centre). */
    static GridGeometry parseWorldFile(Path world, int width, int height) throws IOException {
        String[] words = Files.readString(world, StandardCharsets.ISO_8859_1).strip().split("\\s+");
        if (words.length < 6) {
            throw new DrapeFileException(world, "a world file holds six numbers (A, D, B, E, C, F), one per line;"
                    + " this one has " + (words[0].isEmpty() ? 0 : words.length));
        }
        double[] v = new double[6];
        for (int i = 0; i < 6; i++) {
            try {
                v[i] = Double.parseDouble(words[i]);
            } catch (NumberFormatException e) {
                throw new DrapeFileException(world, "line " + (i + 1) + " is '" + words[i] + "', not a number");
            }
            if (!Double.isFinite(v[i])) {
                throw new DrapeFileException(world, "line " + (i + 1) + " is not a finite number");
            }
        }
        if (v[1] != 0 || v[2] != 0) {
            throw new DrapeFileException(world, "the image is rotated (rotation terms " + v[1] + ", " + v[2]
                    + "); only north-up images are draped: warp it first, e.g. gdalwarp");
        }
        if (!(v[0] > 0) || !(v[3] < 0)) {
            throw new DrapeFileException(world, "the pixel size is " + v[0] + " × " + v[3] + "; a north-up image has"
                    + " A > 0 and E < 0");
        }
        double cellW = v[0];
        double cellH = -v[3];
        try {
            return new GridGeometry(width, height, v[4] - cellW / 2, v[5] + cellH / 2, cellW, cellH,
                    CrsInfo.UNKNOWN, PixelAnchor.CORNER);
        } catch (IllegalArgumentException e) {
            throw new DrapeFileException(world, e.getMessage());
        }
    }

    /** The image with the CRS of its {@code .prj} or {@code .aux.xml}, or none (the DEM's). */
    private static DrapeImage withSidecarCrs(Path file, GridGeometry grid) throws IOException {
        Path prj = SidecarCrs.sibling(file, "prj");
        Path aux = file.resolveSibling(file.getFileName() + ".aux.xml");
        String wkt = null;
        Path from = null;
        if (Files.isRegularFile(prj)) {
            wkt = Files.readString(prj, StandardCharsets.ISO_8859_1);
            from = prj;
        } else if (Files.isRegularFile(aux)) {
            Matcher m = SRS.matcher(Files.readString(aux, StandardCharsets.UTF_8));
            if (m.find()) {
                wkt = m.group(1).replace("&lt;", "<").replace("&gt;", ">").replace("&quot;", "\"")
                        .replace("&apos;", "'").replace("&amp;", "&");
                from = aux;
            }
        }
        if (wkt == null) {
            return new DrapeImage(file, grid, false);
        }
        try {
            return new DrapeImage(file, grid.withCrs(CrsResolver.fromWkt(wkt)), true);
        } catch (IllegalArgumentException e) {
            throw new DrapeFileException(from, e.getMessage());
        }
    }

    /**
     * Decodes a rectangle of pixels.
     *
     * @param col    first column
     * @param row    first row
     * @param width  columns, ≥ 1
     * @param height rows, ≥ 1
     * @return non-premultiplied 0xAARRGGBB, row-major, {@code width} across (opaque where the image has no alpha)
     * @throws IOException when the pixels cannot be decoded; the message names the file
     */
    public int[] readArgb(int col, int row, int width, int height) throws IOException {
        return readArgb(col, row, width, height, 1, 1);
    }

    /**
     * Decodes every {@code stepX}-th column and {@code stepY}-th row of a part of the image: columns {@code col + i ·
     * stepX} for i &lt; {@code width}, rows {@code row + j · stepY} for j &lt; {@code height}. The decoder skips the
     * other pixels as it goes, so an image much finer than the picture is never held whole.
     *
     * @param col    first column
     * @param row    first row
     * @param width  columns returned, ≥ 1
     * @param height rows returned, ≥ 1
     * @param stepX  the column step, ≥ 1
     * @param stepY  the row step, ≥ 1
     * @return non-premultiplied 0xAARRGGBB, row-major, {@code width} across (opaque where the image has no alpha)
     * @throws IOException when the pixels cannot be decoded; the message names the file
     */
    public int[] readArgb(int col, int row, int width, int height, int stepX, int stepY) throws IOException {
        long lastCol = col + (long) (width - 1) * stepX;
        long lastRow = row + (long) (height - 1) * stepY;
        if (col < 0 || row < 0 || width < 1 || height < 1 || stepX < 1 || stepY < 1 || lastCol >= grid.width()
                || lastRow >= grid.height()) {
            throw new IllegalArgumentException("pixels from " + col + "," + row + ", " + width + "×" + height
                    + " every " + stepX + "×" + stepY + ", are not inside the " + grid.width() + "×"
                    + grid.height() + " image");
        }
        boolean tiff = SidecarCrs.extension(file).startsWith("tif");
        // TwelveMonkeys (3.15.0) fails on regions narrower than a tiled image, and its subsampling picks samples of
        // neighbouring pixels: TIFFs are decoded at full width and resolution, and the pixels picked here
        int readCol = tiff ? 0 : col;
        int readWidth = tiff ? grid.width() : (int) (lastCol - col + 1);
        int pickX = tiff ? stepX : 1;
        int pickY = tiff ? stepY : 1;
        ImageReader reader = tiff ? new TIFFImageReaderSpi().createReaderInstance() : readerOf(file);
        BufferedImage image;
        try (ImageInputStream in = new FileImageInputStream(file.toFile())) {
            reader.setInput(in, true, true);
            ImageReadParam param = reader.getDefaultReadParam();
            param.setSourceRegion(new Rectangle(readCol, row, readWidth, (int) (lastRow - row + 1)));
            if (!tiff && (stepX > 1 || stepY > 1)) {
                param.setSourceSubsampling(stepX, stepY, 0, 0);
            }
            image = reader.read(0, param);
        } catch (IOException | RuntimeException e) {
            throw new DrapeFileException(file, "cannot decode its pixels (" + e.getMessage() + ")", e);
        } finally {
            reader.dispose();
        }
        int skip = col - readCol;
        if (image.getWidth() <= skip + (width - 1) * pickX || image.getHeight() <= (height - 1) * pickY) {
            throw new DrapeFileException(file, "the decoder gave " + image.getWidth() + "×" + image.getHeight()
                    + " pixels, fewer than asked for");
        }
        return argb(image, skip, pickX, pickY, width, height);
    }

    /** Every {@code stepX}-th pixel of every {@code stepY}-th row of {@code image} from column {@code skip}. */
    private int[] argb(BufferedImage image, int skip, int stepX, int stepY, int width, int height)
            throws DrapeFileException {
        Raster raster = image.getRaster();
        ColorModel cm = image.getColorModel();
        int bands = raster.getNumBands();
        int[] out = new int[width * height];
        int[] px = new int[bands];
        boolean premultiplied = cm.isAlphaPremultiplied();
        for (int r = 0; r < height; r++) {
            for (int c = 0; c < width; c++) {
                raster.getPixel(skip + c * stepX, r * stepY, px);
                int argb;
                if (cm instanceof IndexColorModel index) {
                    argb = index.getRGB(px[0]);
                } else {
                    argb = switch (bands) {
                        case 1 -> 0xFF000000 | px[0] << 16 | px[0] << 8 | px[0];
                        case 2 -> unpremultiply(px[1], px[0], px[0], px[0], premultiplied);
                        case 3 -> 0xFF000000 | px[0] << 16 | px[1] << 8 | px[2];
                        case 4 -> unpremultiply(px[3], px[0], px[1], px[2], premultiplied);
                        default -> throw new DrapeFileException(file, bands + " bands decoded; a drape is gray,"
                                + " RGB or RGBA");
                    };
                }
                out[r * width + c] = argb;
            }
        }
        return out;
    }

    private static int unpremultiply(int a, int red, int green, int blue, boolean premultiplied) {
        if (a == 0) {
            return 0;
        }
        if (premultiplied && a < 255) {
            red = Math.min(255, (red * 255 + a / 2) / a);
            green = Math.min(255, (green * 255 + a / 2) / a);
            blue = Math.min(255, (blue * 255 + a / 2) / a);
        }
        return a << 24 | red << 16 | green << 8 | blue;
    }
}
