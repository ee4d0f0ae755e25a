package io.github.jdem846.cli;

import io.github.jdem846.output.ImageOutput;
import io.github.jdem846.output.WriteOptions;
import java.nio.file.Path;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.Option;
import picocli.CommandLine.TypeConversionException;
import picocli.CommandLine.Spec;

/** {@code -o OUT}, {@code --world-file} and {@code --cog}: where and how the picture is written (atomically). */
@Command(addMethodSubcommands = false) // no command methods to look for: a quicker start
public final class OutputOptions {

    @Option(names = {"-o", "--output"}, required = true, paramLabel = "OUT",
            description = "The image to write: .png, .tif/.tiff for a GeoTIFF, or .jpg/.jpeg. Written to a temporary file "
                    + "first and moved into place, so a failure leaves nothing behind.")
    Path output;

    @Option(names = "--world-file",
            description = "Also write a world file (.pgw/.tfw), a .prj and a GDAL .aux.xml so GIS software "
                    + "places the image (a GeoTIFF carries its georeferencing anyway).")
    boolean worldFile;

    @Option(names = "--cog",
            description = "Write the GeoTIFF as a Cloud-Optimized GeoTIFF: 512×512 tiles, Deflate, overviews "
                    + "(gdalinfo reports LAYOUT=COG). Only with a .tif/.tiff output.")
    boolean cog;

    @Option(names = "--quality", paramLabel = "1-100", defaultValue = "90", converter = JpegQuality.class,
            description = "JPEG quality, 1 (smallest file) to 100 (best). Default: ${DEFAULT-VALUE}.")
    int quality;

    @Option(names = "--background", paramLabel = "COLOR", converter = BackgroundColor.class,
            description = "Lay the picture on this colour: no-data and outside pixels take it. A name (white, "
                    + "black, gray), #RRGGBB, #RRGGBBAA or R,G,B[,A] (0-255). Default: transparent; white for JPEG, "
                    + "which has no transparency.")
    Integer background;

    @Option(names = {"-q", "--quiet"}, description = "No progress bar.")
    boolean quiet;

    @Option(names = "--progress", description = "Show progress (read, shadows, shading, write, …) even when "
            + "stderr is not a terminal: a line per update, for logs.")
    boolean progress;

    /** The command these options belong to, for usage errors (null when built by hand). */
    @Spec(Spec.Target.MIXEE)
    CommandSpec mixee;

    /**
     * The write options these flags describe; {@code execution} decides whether compression may use all cores.
     *
     * @throws picocli.CommandLine.ParameterException for {@code --cog} with an output that is not a GeoTIFF
     */
    WriteOptions writeOptions(ExecutionOptions execution) {
        WriteOptions options = WriteOptions.defaults()
                .withSidecars(worldFile ? WriteOptions.Sidecars.ALWAYS : WriteOptions.Sidecars.NONE)
                .withParallelCompression(execution.threads() > 1)
                .withTiffLayout(cog ? WriteOptions.TiffLayout.COG : WriteOptions.TiffLayout.STRIPS)
                .withJpegQuality(quality == 0 ? WriteOptions.DEFAULT_JPEG_QUALITY : quality)
                .withBackground(background);
        if (cog && output != null && mixee != null) {
            Usage.check(mixee, "--cog", () -> ImageOutput.filesWritten(output, options));
        }
        return options;
    }

    /** The output path: {@code -o}, or the one named by {@link #use}; null when neither was. */
    Path path() {
        return output;
    }

    /** Writes to {@code path}, named otherwise than with {@code -o} (gdaldem's positional form). */
    void use(Path path) {
        output = path;
    }

    /** {@code --quality}: a whole number 1..100. */
    static final class JpegQuality implements ITypeConverter<Integer> {
        @Override
        public Integer convert(String value) {
            return Converters.checkedInt(value, q -> {
                if (q < 1 || q > 100) {
                    throw new IllegalArgumentException("JPEG quality must be 1..100, got " + q);
                }
            });
        }
    }

    /** {@code --background}: a colour name, {@code #RRGGBB[AA]} or {@code R,G,B[,A]}, as 0xAARRGGBB. */
    static final class BackgroundColor implements ITypeConverter<Integer> {
        private static final String FORMS = "give white, black, gray, #RRGGBB, #RRGGBBAA or R,G,B[,A] with 0-255";

        @Override
        public Integer convert(String value) {
            String v = value.strip().toLowerCase(java.util.Locale.ROOT);
            switch (v) {
                case "white":
                    return 0xFFFFFFFF;
                case "black":
                    return 0xFF000000;
                case "gray", "grey":
                    return 0xFF808080;
                default:
                    break;
            }
            if (v.matches("#[0-9a-f]{6}")) {
                return 0xFF000000 | Integer.parseInt(v.substring(1), 16);
            }
            if (v.matches("#[0-9a-f]{8}")) {
                int rgba = (int) Long.parseLong(v.substring(1), 16);
                return rgba << 24 | rgba >>> 8;
            }
            String[] parts = v.split(",");
            if ((parts.length == 3 || parts.length == 4) && v.matches("[0-9, ]+")) {
                int[] c = new int[4];
                c[3] = 255;
                for (int i = 0; i < parts.length; i++) {
                    String p = parts[i].strip();
                    if (p.isEmpty() || p.length() > 3 || Integer.parseInt(p) > 255) {
                        throw new TypeConversionException("'" + value + "' is not a colour: " + FORMS);
                    }
                    c[i] = Integer.parseInt(p);
                }
                return c[3] << 24 | c[0] << 16 | c[1] << 8 | c[2];
            }
            throw new TypeConversionException("'" + value + "' is not a colour: " + FORMS);
        }
    }
}
