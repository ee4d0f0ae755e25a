package io.github.jdem846.output;

import java.awt.image.BufferedImage;
import java.awt.image.DataBuffer;
import java.io.IOException;
import java.nio.file.Path;
import java.util.Iterator;
import javax.imageio.IIOImage;
import javax.imageio.ImageIO;
import javax.imageio.ImageTypeSpecifier;
import javax.imageio.ImageWriteParam;
import javax.imageio.ImageWriter;
import javax.imageio.metadata.IIOMetadata;
import javax.imageio.plugins.tiff.BaselineTIFFTagSet;
import javax.imageio.plugins.tiff.GeoTIFFTagSet;
import javax.imageio.plugins.tiff.TIFFDirectory;
import javax.imageio.plugins.tiff.TIFFField;
import javax.imageio.plugins.tiff.TIFFTag;
import javax.imageio.stream.FileImageOutputStream;
import javax.imageio.stream.ImageOutputStream;

/**
 * Writes a GeoTIFF with the TIFF plug-in of the JDK ({@code javax.imageio.plugins.tiff}, standard since Java 9):
 * strips of about 256 KiB, Deflate compression (TIFF code 8, "Adobe Deflate", as GDAL writes it) with the horizontal
 * differencing predictor for 8-bit samples, and the georeferencing tags ModelPixelScale (33550), ModelTiepoint
 * (33922), the GeoKey directory (34735–34737) and GDAL_NODATA (42113).
 *
 * <p>Why not TwelveMonkeys' TIFF writer, which is also on the class path: it passes private tags such as the
 * GeoTIFF ones through its {@code TIFFImageMetadata}, but (3.15.0) it cannot write float32 samples ("Not
 * implemented for data type: 4") and writes the whole image as one strip. See docs/output.md.
 */
final class GeoTiffWriter {

    /** The native metadata format of the JDK TIFF plug-in, which {@link TIFFDirectory} reads and writes. */
    static final String JDK_TIFF_METADATA_FORMAT = "javax_imageio_tiff_image_1.0";
    static final int TAG_GDAL_NODATA = 42113;
    private static final int STRIP_BYTES = 1 << 18;

    private GeoTiffWriter() {
    }

    /**
     * Writes {@code image} (8-bit gray, 8-bit RGBA or float32 gray) to {@code file}.
     *
     * @param geo    the georeferencing, or {@code null} for a plain TIFF
     * @param noData the GDAL_NODATA value, or {@code null} for none
     */
    static void write(BufferedImage image, Path file, GeoReference geo, Double noData) throws IOException {
        ImageWriter writer = jdkTiffWriter();
        try (ImageOutputStream out = new FileImageOutputStream(file.toFile())) {
            ImageWriteParam param = writer.getDefaultWriteParam();
            param.setCompressionMode(ImageWriteParam.MODE_EXPLICIT);
            param.setCompressionType("ZLib");
            IIOMetadata defaults = writer.getDefaultImageMetadata(new ImageTypeSpecifier(image), param);
            TIFFDirectory dir = TIFFDirectory.createFromMetadata(defaults);
            addFields(dir, image, geo, noData);
            writer.setOutput(out);
            writer.write(null, new IIOImage(image, null, dir.getAsMetadata()), param);
        } finally {
            writer.dispose();
        }
    }

    private static void addFields(TIFFDirectory dir, BufferedImage image, GeoReference geo, Double noData) {
        BaselineTIFFTagSet baseline = BaselineTIFFTagSet.getInstance();
        int sampleBytes = DataBuffer.getDataTypeSize(image.getSampleModel().getDataType()) / 8;
        int rowBytes = image.getWidth() * image.getSampleModel().getNumBands() * sampleBytes;
        int rowsPerStrip = Math.max(1, Math.min(image.getHeight(), STRIP_BYTES / rowBytes));
        dir.addTIFFField(new TIFFField(baseline.getTag(BaselineTIFFTagSet.TAG_ROWS_PER_STRIP), rowsPerStrip));
        if (sampleBytes == 1) {
            dir.addTIFFField(new TIFFField(baseline.getTag(BaselineTIFFTagSet.TAG_PREDICTOR),
                    BaselineTIFFTagSet.PREDICTOR_HORIZONTAL_DIFFERENCING));
        }
        dir.addTIFFField(new TIFFField(baseline.getTag(BaselineTIFFTagSet.TAG_SOFTWARE), TIFFTag.TIFF_ASCII, 1,
                new String[]{"jdem846"}));
        if (geo != null) {
            GeoTIFFTagSet geoTags = GeoTIFFTagSet.getInstance();
            double sx = geo.pixelWidth(image.getWidth());
            double sy = geo.pixelHeight(image.getHeight());
            dir.addTIFFField(new TIFFField(geoTags.getTag(GeoTIFFTagSet.TAG_MODEL_PIXEL_SCALE), TIFFTag.TIFF_DOUBLE,
                    3, new double[]{sx, sy, 0}));
            // PixelIsArea: raster point (0, 0) is the outer north-west corner of the first pixel.
            dir.addTIFFField(new TIFFField(geoTags.getTag(GeoTIFFTagSet.TAG_MODEL_TIE_POINT), TIFFTag.TIFF_DOUBLE,
                    6, new double[]{0, 0, 0, geo.westX(), geo.northY(), 0}));
            GeoKeyDirectory keys = GeoKeyDirectory.of(geo.crs());
            dir.addTIFFField(new TIFFField(geoTags.getTag(GeoTIFFTagSet.TAG_GEO_KEY_DIRECTORY), TIFFTag.TIFF_SHORT,
                    keys.directory().length, keys.directory()));
            if (keys.doubleParams().length > 0) {
                dir.addTIFFField(new TIFFField(geoTags.getTag(GeoTIFFTagSet.TAG_GEO_DOUBLE_PARAMS),
                        TIFFTag.TIFF_DOUBLE, keys.doubleParams().length, keys.doubleParams()));
            }
            if (!keys.asciiParams().isEmpty()) {
                dir.addTIFFField(new TIFFField(geoTags.getTag(GeoTIFFTagSet.TAG_GEO_ASCII_PARAMS),
                        TIFFTag.TIFF_ASCII, 1, new String[]{keys.asciiParams()}));
            }
        }
        if (noData != null) {
            TIFFTag tag = new TIFFTag("GDAL_NODATA", TAG_GDAL_NODATA, 1 << TIFFTag.TIFF_ASCII);
            dir.addTIFFField(new TIFFField(tag, TIFFTag.TIFF_ASCII, 1, new String[]{noDataText(noData)}));
        }
    }

    /** GDAL_NODATA text: an integer without decimals, NaN as "nan", else the shortest float32 decimal. */
    static String noDataText(double value) {
        if (Double.isNaN(value)) {
            return "nan";
        }
        if (value == Math.rint(value) && Math.abs(value) < 1e15) {
            return Long.toString((long) value);
        }
        return Float.toString((float) value);
    }

    /** The JDK's TIFF writer, told apart from other registered TIFF writers by its metadata format. */
    static ImageWriter jdkTiffWriter() throws IOException {
        for (Iterator<ImageWriter> it = ImageIO.getImageWritersByFormatName("tiff"); it.hasNext(); ) {
            ImageWriter writer = it.next();
            if (JDK_TIFF_METADATA_FORMAT.equals(writer.getOriginatingProvider().getNativeImageMetadataFormatName())) {
                return writer;
            }
            writer.dispose();
        }
        throw new IOException("the JDK's TIFF ImageIO plug-in (javax.imageio.plugins.tiff) is not available");
    }
}
