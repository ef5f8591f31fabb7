//! The mistake catalog's descriptions in Bahasa Indonesia: what the
//! student did, in one line, by the mistake's code. A word table: long on
//! purpose.

use crate::tutor::diagnose::Code;

/// The Indonesian description of a mistake.
pub(super) fn mistake(c: Code) -> &'static str {
    match c {
        Code::CrossOrder => {
            "u = n × Vup, bukan Vup × n (u, dan bersamanya v = n × u, berganti tanda)"
        }
        Code::NReversed => {
            "n dihitung dari Pr − Pe, bukan Pe − Pr (kamera menghadap ke arah yang salah)"
        }
        Code::NNotNormalized => {
            "n = Pe − Pr tidak dibagi dengan |Pe − Pr| (v = n × u pun ikut memiliki panjang itu)"
        }
        Code::UNotNormalized => {
            "u = Vup × n tidak dibagi dengan |Vup × n| (v = n × u pun ikut memiliki panjang itu)"
        }
        Code::UvSwapped => {
            "u dan v tertukar: sumbu x kamera (kanan) ditulis sebagai sumbu y-nya (atas) dan sebaliknya (serta baris matriks transformasi pandang dan koordinat kamera yang mengikutinya)"
        }
        Code::FovyNotHalved => "tan(fovy) dipakai untuk viewing window, bukan tan(fovy/2)",
        Code::DegreesAsRadians => "sudut dalam derajat dimasukkan ke tan seolah-olah dalam radian",
        Code::HeightIsHalfExtent => {
            "setengah ukuran near·tan(fovy/2) (h pada teks) diberikan sebagai tinggi viewing window (dan aspect·h sebagai lebarnya)"
        }
        Code::HeightAsHalfExtent => {
            "near·tan(fovy/2) dianggap tinggi penuh, sehingga tepi-tepi viewing window berada pada setengah jarak yang benar"
        }
        Code::DSign => "tanda d salah (bidang proyeksi z = +near, bukan z = −near)",
        Code::MatrixTransposed => "matriks pandang ditulis tertranspos (konvensi vektor baris P·M)",
        Code::McamAsView => {
            "Mcam, matriks transformasi kamera (koordinat kamera ke koordinat dunia; kolom u, v, n, Pe), diberikan sebagai matriks transformasi pandang V = Mcam⁻¹ (baris u, v, n dan −u·Pe, −v·Pe, −n·Pe)"
        }
        Code::OutcodeReversed => {
            "bit-bit outcode ditulis dengan urutan terbalik (bit 1 paling kiri, bukan paling kanan)"
        }
        Code::EndpointKept => {
            "titik ujung di luar kotak dipertahankan, bukan titik potong yang menggantikannya"
        }
        Code::TFromP1 => {
            "t diukur dari P1, bukan dari P0 (1 − t), serta titik potong, region code-nya dan segmen garis hasil clipping yang mengikutinya dari P(t) = P0 + t·(P1 − P0)"
        }
        Code::ReflectPlusL => "R dihitung sebagai 2N(L·N) + L, bukan 2N(L·N) − L",
        Code::SpecularNoMax => {
            "komponen specular tanpa max(·, 0): cos β yang negatif dipangkatkan n"
        }
        Code::PixelYFromTop => {
            "py piksel diukur dari tepi atas (H − py), seperti baris berkas gambar dihitung, bukan dari tepi bawah"
        }
        Code::EyeNoTranslation => {
            "koordinat kamera diambil sebagai (u·P, v·P, n·P), Peye tidak dikurangkan (matriks transformasi pandang tanpa translasinya, serta proyeksi dan piksel yang mengikutinya)"
        }
        Code::AspectInverted => {
            "tepi kanan viewing window diambil sebagai top / aspect, bukan aspect·top (lebarnya 2·top/aspect, dan piksel yang mengikutinya)"
        }
        Code::LightNotNormalized => {
            "L tidak dibagi dengan |L|: cos α = L·N dengan vektor cahaya apa adanya (serta R = 2N(L·N) − L, cos β dan komponen-komponen yang mengikutinya)"
        }
        Code::NormalNotNormalized => {
            "N tidak dibagi dengan |N|: cos α = L·N dengan normal apa adanya (serta R, cos β dan komponen-komponen yang mengikutinya)"
        }
        Code::CosInRadians => {
            "kosinus sudut dalam derajat dihitung dalam mode radian (cos 45 dibaca sebagai kosinus 45 rad): cos(θ/2) dan cos(φ/2) sumber cahaya spot, serta faktor spot dan komponen-komponen yang mengikutinya"
        }
        Code::CopiedMisprint => {
            "nilai yang dicetak sumber, yang menurut erratanya salah (lihat erratanya)"
        }
    }
}
